// What a computation tells its user besides its result: facts worth knowing (which geometry was
// wrapped) and warnings (a result that may not be what was meant, and why). The filters print them;
// an error is a Status instead.
#ifndef ShrinkWrap_Notes_h
#define ShrinkWrap_Notes_h

#include <string>
#include <vector>

namespace shrinkwrap
{

struct Note
{
  enum Kind
  {
    Info,
    Warning
  } kind = Info;
  std::string text; // a sentence for the user, without the final period
};

using Notes = std::vector<Note>;

inline void inform(Notes& notes, std::string text)
{
  notes.push_back({ Note::Info, std::move(text) });
}

inline void warn(Notes& notes, std::string text)
{
  notes.push_back({ Note::Warning, std::move(text) });
}

} // namespace shrinkwrap

#endif
