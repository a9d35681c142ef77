// vsSceneValues.cxx — reading one JSON value of a scene file: its type and range checked, errors
// naming the key path (vsSceneValues.h).
#include "vsSceneValues.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace vstool::sceneio
{
[[noreturn]] void Fail(const std::string& key, const std::string& message)
{
  throw std::runtime_error((key.empty() ? std::string("scene") : key) + ": " + message);
}

std::string Join(const std::string& path, const std::string& key)
{
  return path.empty() ? key : path + "." + key;
}

std::string At(const std::string& path, size_t i)
{
  return path + "[" + std::to_string(i) + "]";
}

std::string Num(double v)
{
  std::ostringstream s;
  s << v;
  return s.str();
}

std::string List(const std::vector<std::string>& names)
{
  std::string s;
  for (size_t i = 0; i < names.size(); ++i)
  {
    s += (i ? ", " : "") + names[i];
  }
  return s;
}

void RequireObject(const json& v, const std::string& key)
{
  if (!v.is_object())
  {
    Fail(key, std::string("expected an object, got ") + v.type_name());
  }
}

void CheckKeys(const json& obj, const std::string& path, const std::vector<std::string>& allowed)
{
  for (auto it = obj.begin(); it != obj.end(); ++it)
  {
    if (std::find(allowed.begin(), allowed.end(), it.key()) == allowed.end())
    {
      Fail(Join(path, it.key()), "unknown key (expected " + List(allowed) + ")");
    }
  }
}

const json& Require(const json& obj, const std::string& path, const std::string& key)
{
  if (!obj.contains(key))
  {
    Fail(Join(path, key), "missing required key");
  }
  return obj.at(key);
}

double Number(const json& v, const std::string& key)
{
  if (!v.is_number())
  {
    Fail(key, std::string("expected a number, got ") + v.type_name());
  }
  const double d = v.get<double>();
  if (!std::isfinite(d))
  {
    Fail(key, "expected a finite number");
  }
  return d;
}

// The renderer computes in float: a finite double beyond float's range became an infinity or a
// zero on the device (issue 13, item 5), so such values are refused naming the key and the limit.
constexpr double kFloatMax = double(std::numeric_limits<float>::max());
constexpr double kFloatMinNormal = double(std::numeric_limits<float>::min());

double FitsFloat(double d, const std::string& key)
{
  if (!(std::abs(d) <= kFloatMax))
  {
    Fail(key, Num(d) + " is outside the range of float, which the renderer computes in (magnitude at most " +
        Num(kFloatMax) + ")");
  }
  return d;
}

double PositiveFloat(const json& v, const std::string& key, const std::string& what)
{
  const double d = Number(v, key);
  if (!(d > 0.0))
  {
    Fail(key, what + " must be positive, got " + Num(d));
  }
  if (!(d >= kFloatMinNormal && d <= kFloatMax))
  {
    Fail(key, what + " " + Num(d) + " is outside the range of float, which the renderer computes in (between " +
        Num(kFloatMinNormal) + " and " + Num(kFloatMax) + ")");
  }
  return d;
}

double NumberIn(const json& v, const std::string& key, double lo, double hi, const std::string& what)
{
  const double d = Number(v, key);
  if (d < lo || d > hi)
  {
    Fail(key, what + " " + Num(d) + " not in [" + Num(lo) + ", " + Num(hi) + "]");
  }
  return d;
}

double Positive(const json& v, const std::string& key, const std::string& what)
{
  const double d = Number(v, key);
  if (!(d > 0.0))
  {
    Fail(key, what + " must be positive, got " + Num(d));
  }
  return d;
}

double NonNegative(const json& v, const std::string& key, const std::string& what)
{
  const double d = Number(v, key);
  if (d < 0.0)
  {
    Fail(key, what + " must not be negative, got " + Num(d));
  }
  return d;
}

int Integer(const json& v, const std::string& key, long long lo, long long hi, const std::string& what)
{
  if (!v.is_number())
  {
    Fail(key, std::string("expected an integer, got ") + v.type_name());
  }
  long long i = 0;
  if (v.is_number_integer())
  {
    i = v.is_number_unsigned() ? static_cast<long long>(std::min<unsigned long long>(v.get<unsigned long long>(),
                                   static_cast<unsigned long long>(std::numeric_limits<long long>::max())))
                               : v.get<long long>();
  }
  else
  {
    const double d = v.get<double>();
    if (!std::isfinite(d) || d != std::floor(d) || std::abs(d) > 9e15)
    {
      Fail(key, "expected an integer, got " + Num(d));
    }
    i = static_cast<long long>(d);
  }
  if (i < lo || i > hi)
  {
    Fail(key, what + " " + std::to_string(i) + " not in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
  }
  return static_cast<int>(i);
}

bool Boolean(const json& v, const std::string& key)
{
  if (!v.is_boolean())
  {
    Fail(key, std::string("expected true or false, got ") + v.type_name());
  }
  return v.get<bool>();
}

std::string String(const json& v, const std::string& key)
{
  if (!v.is_string())
  {
    Fail(key, std::string("expected a string, got ") + v.type_name());
  }
  return v.get<std::string>();
}

Vec3 Color3(const json& v, const std::string& key, const std::string& what)
{
  Vec3 c = Numbers<3>(v, key);
  for (size_t i = 0; i < 3; ++i)
  {
    if (c[i] < 0.0)
    {
      Fail(At(key, i), what + " must not be negative, got " + Num(c[i]));
    }
    FitsFloat(c[i], At(key, i));
  }
  return c;
}

Vec3 Point3(const json& v, const std::string& key)
{
  Vec3 p = Numbers<3>(v, key);
  for (size_t i = 0; i < 3; ++i)
  {
    FitsFloat(p[i], At(key, i));
  }
  return p;
}

Vec3 Direction(const json& v, const std::string& key)
{
  Vec3 d = Numbers<3>(v, key);
  if (d[0] == 0.0 && d[1] == 0.0 && d[2] == 0.0)
  {
    Fail(key, "the direction must not be zero");
  }
  return d;
}

std::string ResolvePath(const std::string& file, const std::string& baseDir, const std::string& key)
{
  if (file.empty())
  {
    Fail(key, "empty file name");
  }
  std::filesystem::path p(file);
  if (p.is_relative() && !baseDir.empty())
  {
    p = std::filesystem::path(baseDir) / p;
  }
  return p.lexically_normal().string();
}

bool IsPowerOfTwo(int v)
{
  return v > 0 && (v & (v - 1)) == 0;
}

int NameIndex(const std::vector<std::string>& names, const std::string& name, const std::string& key,
  const std::string& what)
{
  auto it = std::find(names.begin(), names.end(), name);
  if (it == names.end())
  {
    Fail(key, "unknown " + what + " '" + name + "' (expected " + List(names) + ")");
  }
  return static_cast<int>(it - names.begin());
}
}
