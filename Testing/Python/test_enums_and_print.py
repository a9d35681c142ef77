"""Issue 14 ("a good VTK citizen"): every enum of VisSweep's VTK classes has a Get...AsString()
that names each of its values, PrintSelf prints the setting as that word, and PrintSelf prints
every value a Get...() macro of the class exposes (settings and counters).

The lists come from the public headers themselves (VISSWEEP_SOURCE=<repository root>), so a
getter or an enum added later without a word or a line in PrintSelf fails here. Run by ctest
with PYTHONPATH=<build>; no device or display is needed (nothing renders)."""
import os
import re
import unittest

import vissweep  # noqa: F401  (the classes)
from vissweep import vissweepFilters, vissweepRendering

SOURCE = os.environ["VISSWEEP_SOURCE"]
HEADERS = {
    "vtkVisibilitySweepVolumeMapper": ("Rendering/vtkVisibilitySweepVolumeMapper.h", vissweepRendering),
    "vtkEnvironmentMapBackground": ("Rendering/vtkEnvironmentMapBackground.h", vissweepRendering),
    "vtkVisibilityGridFilter": ("Filters/vtkVisibilityGridFilter.h", vissweepFilters),
    "vtkEnvironmentMapSource": ("Filters/vtkEnvironmentMapSource.h", vissweepFilters),
    "vtkEnvironmentMapReader": ("Filters/vtkEnvironmentMapReader.h", vissweepFilters),
    "vtkOpenVDBVolumeReader": ("Filters/vtkOpenVDBVolumeReader.h", vissweepFilters),
    "vtkVisSweepDevice": ("Filters/vtkVisSweepDevice.h", vissweepFilters),
}


def header(name):
    path, module = HEADERS[name]
    with open(os.path.join(SOURCE, path), encoding="utf-8") as f:
        text = f.read()
    return re.sub(r"//[^\n]*", "", text), getattr(module, name)


def enums(text):
    """{enum name: [(constant, value), ...]} for `enum Name { A = 0, B = 1 };`."""
    out = {}
    for m in re.finditer(r"\benum\s+(\w+)\s*\{([^}]*)\}", text):
        values, next_value = [], 0
        for item in m.group(2).split(","):
            item = item.strip()
            if not item:
                continue
            name, _, value = item.partition("=")
            value = int(value.strip(), 0) if value.strip() else next_value
            values.append((name.strip(), value))
            next_value = value + 1
        out[m.group(1)] = values
    return out


def enum_setting(text, constants):
    """The setting whose vtkSetClampMacro bounds are the enum's first and last constants."""
    lo, hi = constants[0][0], constants[-1][0]
    m = re.search(r"vtkSetClampMacro\((\w+),\s*int,\s*%s,\s*%s\)" % (lo, hi), text)
    return m.group(1) if m else None


def getters(text):
    names = set(re.findall(r"vtkGet(?:Vector[0-9])?Macro\((\w+),", text))
    names |= set(re.findall(r"^\s*(?:(?:unsigned\s+)?int|double|bool|vtkIdType)\s+Get(\w+)\(\)\s*;", text, re.M))
    names |= set(re.findall(r"vtkGetStringMacro\((\w+)\)", text))
    return names


class EnumsAndPrintSelf(unittest.TestCase):
    def test_every_enum_has_words(self):
        checked = 0
        for name in HEADERS:
            text, cls = header(name)
            for enum, constants in enums(text).items():
                with self.subTest(cls=name, enum=enum):
                    setting = enum_setting(text, constants)
                    self.assertIsNotNone(setting, "%s::%s: no vtkSetClampMacro over its values" % (name, enum))
                    self.assertTrue(hasattr(cls, "Get%sAsString" % setting),
                                    "%s has no Get%sAsString() for enum %s" % (name, setting, enum))
                    obj = cls()
                    # The words a user may expect: the constant's name, or the suffix of the
                    # Set<Setting>To<Suffix>() that sets the value (VTK's convention).
                    suffixes = {}
                    for attr in dir(obj):
                        if attr.startswith("Set%sTo" % setting):
                            probe = cls()
                            getattr(probe, attr)()
                            suffixes.setdefault(getattr(probe, "Get%s" % setting)(), set()).add(
                                attr[len("Set%sTo" % setting):])
                    words = set()
                    for constant, value in constants:
                        getattr(obj, "Set%s" % setting)(value)
                        self.assertEqual(getattr(obj, "Get%s" % setting)(), value)
                        word = getattr(obj, "Get%sAsString" % setting)()
                        self.assertIn(word, {constant} | suffixes.get(value, set()),
                                      "%s::Get%sAsString() for %s" % (name, setting, constant))
                        words.add(word)
                        self.assertIn("%s: %s\n" % (setting, word), str(obj),
                                      "%s's PrintSelf prints %s as a word" % (name, setting))
                        checked += 1
                    self.assertEqual(len(words), len(constants), "%s: distinct words per value" % enum)
        self.assertGreater(checked, 20)

    def test_print_self_prints_every_getter(self):
        for name in HEADERS:
            text, cls = header(name)
            printed = str(cls())
            for getter in sorted(getters(text)):
                with self.subTest(cls=name, getter=getter):
                    self.assertTrue(re.search(r"\n\s*%s: " % re.escape(getter), printed),
                                    "%s's PrintSelf does not print %s" % (name, getter))

    def test_the_strategies_print_as_words(self):
        m = vissweep.vtkVisibilitySweepVolumeMapper()
        for strategy in ("Uniform", "Environment", "Visibility", "Combined", "TwoStep", "Auto"):
            getattr(m, "SetSamplingStrategyTo" + strategy)()
            self.assertEqual(m.GetSamplingStrategyAsString(), strategy)
            self.assertIn("SamplingStrategy: %s\n" % strategy, str(m))


if __name__ == "__main__":
    unittest.main()
