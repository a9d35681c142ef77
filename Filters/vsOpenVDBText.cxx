// vsOpenVDBText.cxx — text read from a .vdb file, made fit for messages (vsOpenVDBText.h).
#include "vsOpenVDBText.h"

#include <cstddef>
#include <new>
#include <string>

namespace vs
{
std::string Printable(const std::string& s)
{
  std::string out;
  out.reserve(s.size());
  for (std::size_t i = 0; i < s.size();)
  {
    const unsigned char c = static_cast<unsigned char>(s[i]);
    std::size_t n = c < 0x80 ? 1
      : (c >> 5) == 0x6      ? 2
      : (c >> 4) == 0xe      ? 3
      : (c >> 3) == 0x1e     ? 4
                             : 0;
    bool valid = n > 0 && i + n <= s.size() && (n > 1 || c >= 0x20 || c == '\t' || c == '\n');
    for (std::size_t k = 1; valid && k < n; ++k)
    {
      valid = (static_cast<unsigned char>(s[i + k]) >> 6) == 0x2;
    }
    if (valid && c != 0x7f)
    {
      out.append(s, i, n);
      i += n;
    }
    else
    {
      out += '?';
      ++i;
    }
  }
  return out;
}

std::string Quote(const std::string& s)
{
  return "\"" + Printable(s) + "\"";
}

std::string Describe(const std::exception& e)
{
  std::string what = e.what() ? e.what() : "";
  if (dynamic_cast<const std::bad_alloc*>(&e))
  {
    what = "out of memory (a corrupt size?)";
  }
  return Printable(what);
}
}
