// Per-vertex data of a SurfaceMesh that follows its edits, typed and named (pmp-library's
// properties are the model): SurfaceMesh::addVertexProperty<double>("v:edgeSize") gives a handle
// that reads and writes the values by vertex. A handle lives until its property is removed or its
// mesh is destroyed, assigned or copied from (a copy's properties are its own: ask it by name).
#ifndef ShrinkWrap_VertexProperties_h
#define ShrinkWrap_VertexProperties_h

#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace shrinkwrap
{

namespace detail
{
// The value a split gives its new vertex: interpolated. A type may say otherwise by a function
// between(a, b, t) of its own, found beside the type (a track id is new, say).
template <typename T>
T between(const T& a, const T& b, double t)
{
  return (1 - t) * a + t * b;
}

// One property's values, whatever their type, as the mesh's edits move them.
class PropertyArray
{
public:
  virtual ~PropertyArray() = default;
  virtual std::unique_ptr<PropertyArray> clone() const = 0;
  virtual void resize(std::size_t n) = 0;                 // new vertices get the default value
  virtual void appendBetween(int a, int b, double t) = 0; // between(value(a), value(b), t)
  virtual void move(int from, int to) = 0;                // value(to) = value(from)
};

template <typename T>
class TypedArray final : public PropertyArray
{
public:
  explicit TypedArray(const T& value)
    : Default(value)
  {
  }
  std::unique_ptr<PropertyArray> clone() const override
  {
    return std::make_unique<TypedArray<T>>(*this);
  }
  void resize(std::size_t n) override { this->Values.resize(n, this->Default); }
  void appendBetween(int a, int b, double t) override
  {
    using detail::between;
    this->Values.push_back(between(this->Values[a], this->Values[b], t));
  }
  void move(int from, int to) override { this->Values[to] = this->Values[from]; }

  std::vector<T> Values;
  T Default;
};
} // namespace detail

// A handle to a property's values; false when there is no such property.
template <typename T>
class VertexProperty
{
public:
  VertexProperty() = default;
  explicit VertexProperty(detail::TypedArray<T>* array)
    : Array(array)
  {
  }
  explicit operator bool() const { return this->Array != nullptr; }
  T& operator[](int v) const { return this->Array->Values[v]; }
  std::vector<T>& values() const { return this->Array->Values; } // one per vertex

private:
  detail::TypedArray<T>* Array = nullptr;
};

// The properties of one mesh, by name.
class VertexProperties
{
public:
  VertexProperties() = default;
  VertexProperties(const VertexProperties& other);
  VertexProperties& operator=(const VertexProperties& other);
  VertexProperties(VertexProperties&&) noexcept = default;
  VertexProperties& operator=(VertexProperties&&) noexcept = default;

  // The property `name` for `count` vertices, made with `value` where it is new (an existing one of
  // another type is replaced).
  template <typename T>
  VertexProperty<T> add(const std::string& name, std::size_t count, const T& value)
  {
    if (VertexProperty<T> found = this->get<T>(name))
    {
      return found;
    }
    this->remove(name);
    auto array = std::make_unique<detail::TypedArray<T>>(value);
    array->resize(count);
    VertexProperty<T> handle(array.get());
    this->Arrays.emplace_back(name, std::move(array));
    return handle;
  }
  // The property `name` of type T, or a false handle.
  template <typename T>
  VertexProperty<T> get(const std::string& name) const
  {
    for (const auto& entry : this->Arrays)
    {
      if (entry.first == name)
      {
        return VertexProperty<T>(dynamic_cast<detail::TypedArray<T>*>(entry.second.get()));
      }
    }
    return VertexProperty<T>();
  }
  void remove(const std::string& name);

  // The mesh's edits, applied to every property.
  void resize(std::size_t n);
  void appendBetween(int a, int b, double t);
  void move(int from, int to);

private:
  std::vector<std::pair<std::string, std::unique_ptr<detail::PropertyArray>>> Arrays;
};

} // namespace shrinkwrap

#endif
