// vsSceneValues.cxx — reading one JSON value of a scene file: its type and range checked, errors
// naming the key path (vsSceneValues.h).
#include "vsSceneValues.h"

#include <algorithm>
#include <cctype>
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
  // Every word also in the API's spelling (RenderMode "AmbientOcclusion", UpdateScheme "RoundRobin"),
  // as the strategies always were: case, '-' and '_' are ignored (issue 35: render.mode refused
  // "Preview" where render.strategy took "TwoStep").
  auto folded = [](const std::string& text) {
    std::string f;
    for (const char c : text)
    {
      if (c != '-' && c != '_')
      {
        f += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
      }
    }
    return f;
  };
  auto it = std::find_if(
    names.begin(), names.end(), [&](const std::string& n) { return folded(n) == folded(name); });
  if (it == names.end())
  {
    Fail(key, "unknown " + what + " '" + name + "' (expected " + List(names) + ")");
  }
  return static_cast<int>(it - names.begin());
}
SceneSection::SceneSection(const json& value, const std::string& section, const std::string& path)
  : Value(value)
  , Section(section)
  , Path(path)
{
  RequireObject(value, path);
  CheckKeys(value, path, SceneSchemaKeys(section));
}

const json& SceneSection::operator[](const std::string& key) const
{
  if (!this->Entry(key).Required && !this->Has(key))
  {
    throw std::logic_error("the scene parser read the absent optional key '" + this->Key(key) + "'");
  }
  return Require(this->Value, this->Path, key);
}

const SceneKey& SceneSection::Typed(const std::string& key, std::initializer_list<SceneType> types) const
{
  const SceneKey& e = this->Entry(key);
  if (std::find(types.begin(), types.end(), e.Type) == types.end())
  {
    throw std::logic_error("the scene parser read '" + this->Key(key) + "' as another type than the schema's");
  }
  return e;
}

int SceneSection::Integer(const std::string& key) const
{
  const SceneKey& e = this->Typed(key, { SceneType::Integer });
  return this->Integer(key, static_cast<long long>(e.Min), static_cast<long long>(e.Max));
}

int SceneSection::Integer(const std::string& key, long long lo, long long hi) const
{
  const SceneKey& e = this->Typed(key, { SceneType::Integer });
  if (e.Range != SceneRange::Closed)
  {
    throw std::logic_error("the scene schema gives the integer '" + this->Key(key) + "' a range other than [Min, Max]");
  }
  return sceneio::Integer((*this)[key], this->Key(key), lo, hi, e.Noun);
}

double SceneSection::Number(const std::string& key) const
{
  const SceneKey& e = this->Typed(key, { SceneType::Number });
  const json& v = (*this)[key];
  const std::string k = this->Key(key);
  switch (e.Range)
  {
    case SceneRange::Any:
      return sceneio::Number(v, k);
    case SceneRange::Closed:
      return NumberIn(v, k, e.Min, e.Max, e.Noun);
    case SceneRange::LeftOpen:
    case SceneRange::Open:
    {
      const double d = sceneio::Number(v, k);
      const bool open = e.Range == SceneRange::Open;
      if (!(d > e.Min && (open ? d < e.Max : d <= e.Max)))
      {
        Fail(k, std::string(e.Noun) + " " + Num(d) + " not in (" + Num(e.Min) + ", " + Num(e.Max) + (open ? ")" : "]") +
            e.Unit);
      }
      return d;
    }
    case SceneRange::Positive:
      return Positive(v, k, e.Noun);
    case SceneRange::PositiveFloat:
      return PositiveFloat(v, k, e.Noun);
    case SceneRange::NonNegativeFloat:
      return FitsFloat(NonNegative(v, k, e.Noun), k);
  }
  throw std::logic_error("unknown range of '" + k + "'");
}

bool SceneSection::Boolean(const std::string& key) const
{
  this->Typed(key, { SceneType::Boolean });
  return sceneio::Boolean((*this)[key], this->Key(key));
}

std::string SceneSection::String(const std::string& key) const
{
  const SceneKey& e = this->Typed(key, { SceneType::String, SceneType::Word });
  const std::string k = this->Key(key);
  const std::string s = sceneio::String((*this)[key], k);
  if (e.Type == SceneType::String)
  {
    return s;
  }
  // Words also in the API's spelling ("TwoStep"), stored as the scene file spells them.
  return e.Words[NameIndex(e.Words, s, k, e.Noun)];
}

Vec3 SceneSection::Vector(const std::string& key) const
{
  const SceneKey& e = this->Typed(key, { SceneType::Point, SceneType::Direction, SceneType::Color });
  const json& v = (*this)[key];
  switch (e.Type)
  {
    case SceneType::Point:
      return Point3(v, this->Key(key));
    case SceneType::Direction:
      return Direction(v, this->Key(key));
    default:
      return Color3(v, this->Key(key), e.Noun);
  }
}

std::string SceneSection::File(const std::string& key, const std::string& baseDir) const
{
  this->Typed(key, { SceneType::File });
  const std::string k = this->Key(key);
  return ResolvePath(sceneio::String((*this)[key], k), baseDir, k);
}
}
