// vtkFXArguments: strict parsing of the command-line tools' values
// (vtkfx-render, vtkfx-bench, vtkfx-compare), so that a typo is an error
// rather than a zero: atoi and atof read "abc" as 0.
#ifndef vtkFXArguments_h
#define vtkFXArguments_h

#include <cstdlib>
#include <sstream>
#include <string>

namespace vtkFXArguments
{
// WxH (or WXH), each side 1..16384 pixels (OpenGL's usual largest texture),
// nothing after it.
inline bool ParseSize(const std::string& text, int& w, int& h)
{
  char x = 0;
  std::istringstream in(text);
  long lw = 0, lh = 0;
  if (!(in >> lw >> x >> lh) || (x != 'x' && x != 'X') || !in.eof())
  {
    return false;
  }
  if (lw < 1 || lh < 1 || lw > 16384 || lh > 16384)
  {
    return false;
  }
  w = static_cast<int>(lw);
  h = static_cast<int>(lh);
  return true;
}

// The value after the option at argv[i], moving i to it: false, with i
// unchanged, where there is none, it is empty, or it is the next option
// ("--out --no-ground" wrote an image named --no-ground and drew the
// ground).
inline bool TakeValue(int argc, char* argv[], int& i, std::string& value)
{
  if (i + 1 >= argc)
  {
    return false;
  }
  const std::string next = argv[i + 1];
  if (next.empty() || next.compare(0, 2, "--") == 0)
  {
    return false;
  }
  value = next;
  ++i;
  return true;
}

// A whole decimal number in [lo, hi], nothing after it.
inline bool ParseInt(const std::string& text, int lo, int hi, int& value)
{
  char* end = nullptr;
  const long v = std::strtol(text.c_str(), &end, 10);
  if (text.empty() || *end != '\0' || v < lo || v > hi)
  {
    return false;
  }
  value = static_cast<int>(v);
  return true;
}

// A decimal number (digits, '.', an exponent) in [lo, hi]: no hexadecimal,
// no spaces, nothing that a float uniform would turn into 0 or infinity.
inline bool ParseInRange(const std::string& text, double lo, double hi, double& value)
{
  if (text.empty() || text.find_first_not_of("0123456789.eE+-") != std::string::npos)
  {
    return false;
  }
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (*end != '\0' || !(v >= lo && v <= hi))
  {
    return false;
  }
  value = v;
  return true;
}
}

#endif
