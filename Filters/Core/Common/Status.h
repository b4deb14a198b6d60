// The core's one error convention: work that can fail returns a Status, empty when it succeeded and
// otherwise saying why in words a user can act on (the filters put it in their error messages).
// Results go to out-parameters or the returned object; exceptions are left to std::bad_alloc and
// its kind, which the filters catch.
#ifndef ShrinkWrap_Status_h
#define ShrinkWrap_Status_h

#include <string>
#include <utility>

namespace shrinkwrap
{

class Status
{
public:
  Status() = default;
  static Status failure(std::string message) { return Status(std::move(message)); }

  bool ok() const { return this->Message.empty(); }
  explicit operator bool() const { return this->ok(); }
  const std::string& message() const { return this->Message; }

private:
  explicit Status(std::string message)
    : Message(message.empty() ? "failed" : std::move(message))
  {
  }
  std::string Message;
};

} // namespace shrinkwrap

#endif
