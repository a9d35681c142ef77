// libFuzzer target: the scene-file parser (Tool/vsSceneFile). Contract under test:
// any byte string either parses into a Scene or throws std::runtime_error (with a message
// naming the key path or the JSON position); nothing else escapes, nothing crashes. A scene
// that parses also round-trips: ParseScene(ToJson(s)) == s (vsSceneFile.h promises it).
#include "vsSceneFile.h"

#include "vsFuzzUtilities.h"

#include <stdexcept>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  const std::string text(reinterpret_cast<const char*>(data), size);
  vstool::Scene scene;
  try
  {
    scene = vstool::ParseSceneText(text, "/base");
  }
  catch (const std::runtime_error& e)
  {
    if (std::string(e.what()).empty())
    {
      vsfuzz::Fail("ParseSceneText threw an empty message");
    }
    return 0;
  }
  // Any other exception type propagates out of here: libFuzzer reports it as a crash
  // ("uncaught exception"), which is what the contract forbids.
  vstool::Scene again;
  try
  {
    again = vstool::ParseScene(vstool::ToJson(scene), "/elsewhere");
  }
  catch (const std::runtime_error& e)
  {
    vsfuzz::Fail(std::string("ToJson of a parsed scene does not parse again: ") + e.what() +
      "\nscene: " + vstool::ToJson(scene).dump());
  }
  if (again != scene)
  {
    vsfuzz::Fail("ParseScene(ToJson(s)) != s for " + vstool::ToJson(scene).dump() + "\nagain: " +
      vstool::ToJson(again).dump());
  }
  return 0;
}
