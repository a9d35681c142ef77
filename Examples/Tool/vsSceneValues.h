// vsSceneValues.h — reading one JSON value of a scene file for the parser (vsSceneFile.cxx):
// each reader checks the value's type and range and throws std::runtime_error naming the key
// path ("render.width: width 0 not in [1, 16384]"). Not part of the tool's interface.
#ifndef vsSceneValues_h
#define vsSceneValues_h

#include "vsSceneFile.h"

#include <nlohmann/json.hpp>

#include <array>
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

}

#endif
