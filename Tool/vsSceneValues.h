// vsSceneValues.h — reading one JSON value of a scene file for the parser (vsSceneFile.cxx):
// each reader checks the value's type and range and throws std::runtime_error naming the key
// path ("render.width: width 0 not in [1, 16384]"). SceneSection reads a section's keys by
// their entries in the schema (vsSceneSchema.h). Not part of the tool's interface.
#ifndef vsSceneValues_h
#define vsSceneValues_h

#include "vsSceneFile.h"
#include "vsSceneSchema.h"

#include <nlohmann/json.hpp>

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace vstool::sceneio
{
using json = nlohmann::json;

/** Throws "<key>: <message>" ("scene: ..." for the top level, key ""). */
[[noreturn]] void Fail(const std::string& key, const std::string& message);
/** "render" + "width" -> "render.width"; "" + "volume" -> "volume". */
std::string Join(const std::string& path, const std::string& key);
/** "volume.files" + 2 -> "volume.files[2]". */
std::string At(const std::string& path, size_t i);
/** A number as error messages print it (std::ostream's default, "1e+39"). */
std::string Num(double v);
/** "a, b, c". */
std::string List(const std::vector<std::string>& names);

void RequireObject(const json& v, const std::string& key);
/** Fails on the first key of obj not in allowed, listing the allowed ones. */
void CheckKeys(const json& obj, const std::string& path, const std::vector<std::string>& allowed);
const json& Require(const json& obj, const std::string& path, const std::string& key);

/** A finite number. */
double Number(const json& v, const std::string& key);
/** d itself if float can hold it (magnitude at most float's largest). */
double FitsFloat(double d, const std::string& key);
/** A positive length or scale whose float is neither zero, denormal nor infinite. */
double PositiveFloat(const json& v, const std::string& key, const std::string& what);
double NumberIn(const json& v, const std::string& key, double lo, double hi, const std::string& what);
double Positive(const json& v, const std::string& key, const std::string& what);
double NonNegative(const json& v, const std::string& key, const std::string& what);
/** An integer in [lo, hi] (2.0 is one). */
int Integer(const json& v, const std::string& key, long long lo, long long hi, const std::string& what);
bool Boolean(const json& v, const std::string& key);
std::string String(const json& v, const std::string& key);
/** [r, g, b], each at least 0 and within float's range. */
Vec3 Color3(const json& v, const std::string& key, const std::string& what);
/** A point: every component within float's range. */
Vec3 Point3(const json& v, const std::string& key);
/** Any vector but zero. */
Vec3 Direction(const json& v, const std::string& key);
/** file against baseDir, lexically normal; an empty name fails. */
std::string ResolvePath(const std::string& file, const std::string& baseDir, const std::string& key);
bool IsPowerOfTwo(int v);
/** The index of `name` among a key's allowed words; an error naming the key, the word and the
 *  allowed ones otherwise. */
int NameIndex(const std::vector<std::string>& names, const std::string& name, const std::string& key,
  const std::string& what);

/** An array of N numbers. */
template <size_t N>
std::array<double, N> Numbers(const json& v, const std::string& key)
{
  if (!v.is_array() || v.size() != N)
  {
    Fail(key, "expected an array of " + std::to_string(N) + " numbers, got " +
        (v.is_array() ? std::to_string(v.size()) + " elements" : std::string(v.type_name())));
  }
  std::array<double, N> a{};
  for (size_t i = 0; i < N; ++i)
  {
    a[i] = Number(v[i], At(key, i));
  }
  return a;
}

/** One object of the scene file read by the schema: its keys are checked against the schema's
 *  section (the first unknown one fails, listing the known ones) and each value by its entry's
 *  type and range. `path` names it in errors ("clip_planes[1]" for section "clip_planes[]"). */
class SceneSection
{
public:
  SceneSection(const json& value, const std::string& section, const std::string& path);
  SceneSection(const json& value, const std::string& section)
    : SceneSection(value, section, section)
  {
  }

  bool Has(const std::string& key) const { return this->Value.contains(key); }
  /** The key's path in errors ("render.width"). */
  std::string Key(const std::string& key) const { return Join(this->Path, key); }
  const SceneKey& Entry(const std::string& key) const { return SceneSchemaKey(this->Section, key); }
  /** The raw value; a required key that is absent fails ("missing required key"). */
  const json& operator[](const std::string& key) const;

  // The value of a key checked by its entry; absent fails as operator[] does.
  int Integer(const std::string& key) const;
  /** With bounds that depend on the rest of the scene (the entry's message). */
  int Integer(const std::string& key, long long lo, long long hi) const;
  double Number(const std::string& key) const;
  bool Boolean(const std::string& key) const;
  /** A String, or a Word as the word list spells it. */
  std::string String(const std::string& key) const;
  /** A Point, Direction or Color. */
  Vec3 Vector(const std::string& key) const;
  /** A File, resolved against baseDir. */
  std::string File(const std::string& key, const std::string& baseDir) const;

  // Sets `value` when the key is present; returns whether it was.
  bool Read(const std::string& key, int& value) const { return this->ReadAs(key, value, &SceneSection::Integer); }
  bool Read(const std::string& key, double& value) const { return this->ReadAs(key, value, &SceneSection::Number); }
  bool Read(const std::string& key, bool& value) const { return this->ReadAs(key, value, &SceneSection::Boolean); }
  bool Read(const std::string& key, std::string& value) const
  {
    return this->ReadAs(key, value, &SceneSection::String);
  }
  bool Read(const std::string& key, Vec3& value) const { return this->ReadAs(key, value, &SceneSection::Vector); }
  template <typename T>
  bool Read(const std::string& key, std::optional<T>& value) const
  {
    T v{};
    if (!this->Read(key, v))
    {
      return false;
    }
    value = v;
    return true;
  }

private:
  template <typename T>
  bool ReadAs(const std::string& key, T& value, T (SceneSection::*read)(const std::string&) const) const
  {
    if (!this->Has(key))
    {
      return false;
    }
    value = (this->*read)(key);
    return true;
  }
  /** The key's entry, which must be of one of these types (else std::logic_error: a parser bug). */
  const SceneKey& Typed(const std::string& key, std::initializer_list<SceneType> types) const;

  const json& Value;
  std::string Section;
  std::string Path;
};
}

#endif
