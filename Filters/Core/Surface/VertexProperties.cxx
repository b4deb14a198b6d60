#include "Surface/VertexProperties.h"

#include <algorithm>

namespace shrinkwrap
{

VertexProperties::VertexProperties(const VertexProperties& other)
{
  for (const auto& entry : other.Arrays)
  {
    this->Arrays.emplace_back(entry.first, entry.second->clone());
  }
}

VertexProperties& VertexProperties::operator=(const VertexProperties& other)
{
  if (this != &other)
  {
    VertexProperties copy(other);
    *this = std::move(copy);
  }
  return *this;
}

void VertexProperties::remove(const std::string& name)
{
  this->Arrays.erase(std::remove_if(this->Arrays.begin(), this->Arrays.end(),
                       [&](const auto& entry) { return entry.first == name; }),
    this->Arrays.end());
}

void VertexProperties::resize(std::size_t n)
{
  for (auto& entry : this->Arrays)
  {
    entry.second->resize(n);
  }
}

void VertexProperties::appendBetween(int a, int b, double t)
{
  for (auto& entry : this->Arrays)
  {
    entry.second->appendBetween(a, b, t);
  }
}

void VertexProperties::move(int from, int to)
{
  for (auto& entry : this->Arrays)
  {
    entry.second->move(from, to);
  }
}

} // namespace shrinkwrap
