#include "Evolution/StepCache.h"

#include <set>

namespace shrinkwrap
{

void StepCache::store(int k, Step step)
{
  this->Steps[k] = std::move(step);
  this->Newest = std::max(this->Newest, k);
}

const std::pair<const int, StepCache::Step>& StepCache::atOrBefore(int k) const
{
  const auto found = this->Steps.find(k);
  return found != this->Steps.end() ? *found : *std::prev(this->Steps.upper_bound(k));
}

void StepCache::dropAfter(int k)
{
  this->Steps.erase(this->Steps.upper_bound(k), this->Steps.end());
  this->Newest = this->Steps.empty() ? 0 : this->Steps.rbegin()->first;
}

double StepCache::bytes() const
{
  std::set<const void*> lists;
  double bytes = 0;
  for (const auto& entry : this->Steps)
  {
    bytes += 2.0 * sizeof(Vec3) * entry.second.state.size();
    if (lists.insert(entry.second.triangles.get()).second)
    {
      bytes += sizeof(std::array<int, 3>) * entry.second.triangles->size();
    }
  }
  return bytes;
}

void StepCache::thin(double limit, int kept)
{
  while (this->Stride <= this->Newest && this->bytes() > limit)
  {
    this->Stride *= 2;
    for (auto it = this->Steps.begin(); it != this->Steps.end();)
    {
      const bool keep = it->first % this->Stride == 0 || it->first == this->Newest ||
        it->first == kept || it->second.edited;
      it = keep ? std::next(it) : this->Steps.erase(it);
    }
  }
}

} // namespace shrinkwrap
