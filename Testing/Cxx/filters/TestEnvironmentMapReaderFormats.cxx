// vtkEnvironmentMapReader's errors for missing, corrupt and oversized files, the Radiance .hdr and
// OpenEXR variants it reads, and vtkEnvironmentMapSource's procedural maps.
#include "vsEnvironmentMapTest.h"

TEST(EnvironmentMapReader, Errors)
{
  TempDir tmp;
  // Missing file.
  ExpectErrorNamingFile(tmp.File("does_not_exist.exr"), "missing");
  // A text file named .exr.
  {
    std::ofstream(tmp.File("text.exr")) << "this is not an image\n";
    ExpectErrorNamingFile(tmp.File("text.exr"), "text");
  }
  // An empty file.
  {
    std::ofstream(tmp.File("empty.exr")).flush();
    ExpectErrorNamingFile(tmp.File("empty.exr"), "empty");
  }
  // A real EXR cut short: the header survives, the pixel data does not.
  {
    std::ifstream in(EnvDir + "city.exr", std::ios::binary);
    std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    ASSERT_GT(bytes.size(), 20000u);
    std::ofstream(tmp.File("truncated.exr"), std::ios::binary).write(bytes.data(), 20000);
    ExpectErrorNamingFile(tmp.File("truncated.exr"), "truncated");
    // The EXR magic number followed by garbage.
    std::vector<char> garbage(4096);
    for (std::size_t i = 0; i < garbage.size(); ++i)
    {
      garbage[i] = char((i * 7919u) >> 3);
    }
    std::copy(bytes.begin(), bytes.begin() + 4, garbage.begin());
    std::ofstream(tmp.File("garbage.exr"), std::ios::binary).write(garbage.data(), garbage.size());
    ExpectErrorNamingFile(tmp.File("garbage.exr"), "garbage");
  }
  // A Radiance header with no pixels.
  {
    std::ofstream(tmp.File("short.hdr"), std::ios::binary) << "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 8 +X 16\n";
    ExpectErrorNamingFile(tmp.File("short.hdr"), "short hdr");
  }
  // A directory.
  ExpectErrorNamingFile(tmp.Path.string(), "directory");
  EXPECT_EQ(vtkEnvironmentMapReader::CanReadFile(tmp.File("text.exr").c_str()), 0);
  EXPECT_EQ(vtkEnvironmentMapReader::CanReadFile((EnvDir + "city.exr").c_str()), 1);
  EXPECT_EQ(vtkEnvironmentMapReader::CanReadFile(nullptr), 0);

  // A good file, then a missing one: the output empties (no stale map).
  vtkNew<vtkEnvironmentMapReader> reader;
  reader->SetOctahedralSize(16);
  EXPECT_TRUE(RunReader(reader, EnvDir + "city.exr")->Errors.empty());
  EXPECT_EQ(reader->GetOutput()->GetNumberOfPoints(), 256);
  EXPECT_EQ(RunReader(reader, tmp.File("gone.exr"))->Errors.size(), 1u);
  EXPECT_EQ(reader->GetOutput()->GetNumberOfPoints(), 0);
  EXPECT_FALSE(reader->GetEnvironmentMap());
  EXPECT_EQ(reader->GetTotalPower(), 0.0);
  // And recovers.
  EXPECT_TRUE(RunReader(reader, EnvDir + "city.exr")->Errors.empty());
  EXPECT_EQ(reader->GetOutput()->GetNumberOfPoints(), 256);
  // A size that is not a power of two is an error.
  reader->SetOctahedralSize(48);
  EXPECT_EQ(RunReader(reader, EnvDir + "city.exr")->Errors.size(), 1u);
  EXPECT_EQ(reader->GetOutput()->GetNumberOfPoints(), 0);
}

// Found by the environment map fuzz target: a 400-byte EXR whose header claims a display window
// of 7 x 117,440,512 pixels made the reader allocate 9.8 GB for the lat-long. Headers that claim
// more than MaximumNumberOfPixels are now an error before any allocation.
TEST(EnvironmentMapReader, HeaderClaimingAHugeImageIsRefused)
{
  TempDir tmp;
  ExrSpec huge;
  huge.Channels = { "B", "G", "R" };
  huge.Half = true;
  huge.DisplayW = 7;
  huge.DisplayH = 117440512;
  huge.DataX1 = 6;
  huge.DataY1 = 3;
  WriteExr(tmp.File("huge.exr"), huge, [](int, int, int) { return 1.0f; });
  ExpectErrorNamingFile(tmp.File("huge.exr"), "huge display window");
  {
    vtkNew<vtkEnvironmentMapReader> reader;
    auto msgs = RunReader(reader, tmp.File("huge.exr"));
    ASSERT_EQ(msgs->Errors.size(), 1u);
    EXPECT_NE(msgs->Errors[0].find("7 x 117440512"), std::string::npos) << msgs->Errors[0];
    EXPECT_NE(msgs->Errors[0].find("MaximumNumberOfPixels"), std::string::npos) << msgs->Errors[0];
  }
  // Found by fuzzing: an attribute claiming 2 GB in a 40-byte header made OpenEXR allocate 2 GB
  // before noticing the file is short. The reader now checks attribute sizes against the file.
  {
    std::string bytes("\x76\x2f\x31\x01\x02\x00\x00\x00", 8);
    bytes += std::string("junk\0opaquetype\0", 16);
    bytes += std::string("\x00\xff\xff\x7f", 4); // 2147483392
    bytes += std::string(8, '\0');
    std::ofstream(tmp.File("bigattr.exr"), std::ios::binary).write(bytes.data(), std::streamsize(bytes.size()));
    ExpectErrorNamingFile(tmp.File("bigattr.exr"), "huge attribute");
    vtkNew<vtkEnvironmentMapReader> reader;
    auto msgs = RunReader(reader, tmp.File("bigattr.exr"));
    ASSERT_EQ(msgs->Errors.size(), 1u);
    EXPECT_NE(msgs->Errors[0].find("corrupt header: header attribute 'junk' (opaquetype) claims 2147483392 bytes"),
      std::string::npos) << msgs->Errors[0];
  }
  // A Radiance header claiming 10^10 pixels (and holding none).
  std::ofstream(tmp.File("huge.hdr"), std::ios::binary)
    << "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 100000 +X 100000\n";
  ExpectErrorNamingFile(tmp.File("huge.hdr"), "huge hdr");

  // The limit is the reader's: a 16 x 8 file passes at 128 pixels and fails at 127.
  ExrSpec small;
  small.Channels = { "B", "G", "R" };
  WriteExr(tmp.File("small.exr"), small, [](int, int, int) { return 0.5f; });
  vtkNew<vtkEnvironmentMapReader> reader;
  reader->SetOctahedralSize(8);
  reader->SetMaximumNumberOfPixels(128);
  EXPECT_TRUE(RunReader(reader, tmp.File("small.exr"))->Errors.empty());
  EXPECT_EQ(reader->GetOutput()->GetNumberOfPoints(), 64);
  reader->SetMaximumNumberOfPixels(127);
  auto msgs = RunReader(reader, tmp.File("small.exr"));
  ASSERT_EQ(msgs->Errors.size(), 1u);
  EXPECT_NE(msgs->Errors[0].find("16 x 8 = 128 pixels, more than MaximumNumberOfPixels (127)"), std::string::npos)
    << msgs->Errors[0];
  EXPECT_EQ(reader->GetOutput()->GetNumberOfPoints(), 0);
}

// A Radiance RGBE file written here (uncompressed scanlines, standard -Y H +X W
// orientation: the first scanline is the top of the picture).
TEST(EnvironmentMapReader, RadianceHDR)
{
  TempDir tmp;
  const int w = 32, h = 16;
  std::vector<float> rgb(3 * w * h);
  for (int j = 0; j < h; ++j)
  {
    for (int i = 0; i < w; ++i)
    {
      float* p = &rgb[3 * (j * w + i)];
      p[0] = 0.25f + i / 8.0f;   // grows to the right
      p[1] = 0.5f + 4.0f * j;    // grows downwards
      p[2] = j == 0 ? 1000.0f : 0.125f; // the top row is very bright in blue
    }
  }
  {
    std::ofstream out(tmp.File("ramp.hdr"), std::ios::binary);
    out << "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y " << h << " +X " << w << "\n";
    for (int k = 0; k < w * h; ++k)
    {
      unsigned char e[4];
      ToRGBE(&rgb[3 * k], e);
      out.write(reinterpret_cast<const char*>(e), 4);
    }
  }
  vs::LatLongImage img;
  std::string error;
  ASSERT_TRUE(vtkEnvironmentMapReader::ReadLatLong(tmp.File("ramp.hdr").c_str(), img, error)) << error;
  ASSERT_EQ(img.Width, w);
  ASSERT_EQ(img.Height, h);
  for (int j = 0; j < h; ++j)
  {
    for (int i = 0; i < w; ++i)
    {
      const glm::vec3 got = img.Pixel(i, j);
      for (int c = 0; c < 3; ++c)
      {
        const float want = rgb[3 * (j * w + i) + c];
        // RGBE keeps 8 bits of mantissa relative to the largest channel.
        const float largest = std::max(rgb[3 * (j * w + i)], std::max(rgb[3 * (j * w + i) + 1], rgb[3 * (j * w + i) + 2]));
        EXPECT_NEAR(got[c], want, largest / 128.0f) << i << "," << j << " channel " << c;
      }
    }
  }
  // Through the reader: the bright top row is the zenith (+Z).
  vtkNew<vtkEnvironmentMapReader> reader;
  auto msgs = RunReader(reader, tmp.File("ramp.hdr"));
  EXPECT_TRUE(msgs->Errors.empty());
  auto map = reader->GetEnvironmentMap();
  ASSERT_TRUE(map);
  EXPECT_EQ(map->Size, 16);
  EXPECT_GT(map->Evaluate(glm::vec3(0, 0, 1)).z, 100.0f);
  EXPECT_LT(map->Evaluate(glm::vec3(0, 0, -1)).z, 1.0f);
  EXPECT_NEAR(map->TotalPower(), vs::LatLongPower(img), 0.005 * map->TotalPower());
  // Same map as converting the lat-long directly.
  EXPECT_EQ(map->Radiance, vs::EnvironmentMap::FromLatLong(img).Radiance);
}

TEST(EnvironmentMapSource, TypesAndPower)
{
  vtkNew<vtkEnvironmentMapSource> src;
  src->SetOctahedralSize(32);
  src->SetColor(0.5, 1.0, 2.0);
  src->Update();
  EXPECT_EQ(src->GetOutput()->GetNumberOfPoints(), 1024);
  EXPECT_NEAR(src->GetTotalPower(), 4.0 * Pi * vs::Luminance(glm::vec3(0.5f, 1.0f, 2.0f)), 1e-4);
  EXPECT_STREQ(src->GetTypeAsString(), "Constant");

  src->SetTypeToSunDisk();
  src->SetSunDirection(0.3, -0.5, 0.2);
  src->SetSunAngularRadius(0.5);
  src->SetSunRadiance(2e4, 2e4, 2e4);
  src->SetSkyColor(0, 0, 0);
  src->Update();
  const double r = 0.5 * Pi / 180.0;
  EXPECT_NEAR(src->GetTotalPower(), Pi * r * r * 2e4, 0.01 * Pi * r * r * 2e4);
  auto sun = src->GetEnvironmentMap();
  ASSERT_TRUE(sun);
  EXPECT_GT(sun->Evaluate(glm::vec3(0.3f, -0.5f, 0.2f)).x, 0.0f);

  src->SetTypeToTwoToneSky();
  src->SetUpperColor(1, 1, 1);
  src->SetLowerColor(0, 0, 0);
  src->SetIntensity(3.0);
  src->Update();
  EXPECT_NEAR(src->GetTotalPower(), 3.0 * 2.0 * Pi, 1e-4);
  EXPECT_EQ(src->GetEnvironmentMap()->Evaluate(glm::vec3(0, 0, 1)).x, 3.0f);

  vtkNew<Messages> msgs;
  src->AddObserver(vtkCommand::ErrorEvent, msgs);
  src->SetOctahedralSize(24);
  src->Update();
  EXPECT_EQ(msgs->Errors.size(), 1u);
  EXPECT_EQ(src->GetOutput()->GetNumberOfPoints(), 0);
}

// OpenEXR variants written here: half/float, RGB/RGBA/Y-only, scanline/tiled,
// a data window smaller than the display window.
TEST(EnvironmentMapReader, OpenEXRVariants)
{
  TempDir tmp;
  // Exact in half: multiples of 1/8 up to 64.
  auto value = [](int x, int y, int c) { return 0.125f * float(1 + ((x * 3 + y * 5 + c * 7) % 64)); };
  struct Case
  {
    const char* name;
    std::vector<std::string> channels; // sorted, as in the file
    bool half;
    int tile;
  };
  const Case cases[] = { { "rgb_float_scan", { "B", "G", "R" }, false, 0 },
    { "rgba_half_scan", { "A", "B", "G", "R" }, true, 0 }, { "rgb_half_tiled", { "B", "G", "R" }, true, 4 },
    { "rgba_float_tiled", { "A", "B", "G", "R" }, false, 3 }, { "y_half_scan", { "Y" }, true, 0 },
    { "layer_float_scan", { "diffuse.B", "diffuse.G", "diffuse.R" }, false, 0 } };
  for (const Case& c : cases)
  {
    ExrSpec spec;
    spec.Channels = c.channels;
    spec.Half = c.half;
    spec.Tile = c.tile;
    const std::string file = tmp.File(std::string(c.name) + ".exr");
    // Channel index in the file -> its value function's channel (R=0, G=1, B=2, Y=0, A=9).
    auto fileChannel = [&](int k) {
      const std::string& n = c.channels[k];
      const char last = n.back();
      return last == 'R' || last == 'Y' ? 0 : last == 'G' ? 1 : last == 'B' ? 2 : 9;
    };
    WriteExr(file, spec, [&](int x, int y, int k) { return value(x, y, fileChannel(k)); });
    vs::LatLongImage img;
    std::string error;
    ASSERT_TRUE(vtkEnvironmentMapReader::ReadLatLong(file.c_str(), img, error)) << c.name << ": " << error;
    ASSERT_EQ(img.Width, 16) << c.name;
    ASSERT_EQ(img.Height, 8) << c.name;
    for (int y = 0; y < 8; ++y)
    {
      for (int x = 0; x < 16; ++x)
      {
        for (int k = 0; k < 3; ++k)
        {
          const float want = c.channels.size() == 1 ? value(x, y, 0) : value(x, y, k);
          ASSERT_EQ(img.Pixel(x, y)[k], want) << c.name << " pixel " << x << "," << y << " channel " << k;
        }
      }
    }
  }
  // A data window inside the display window: the rest is black.
  ExrSpec spec;
  spec.Channels = { "B", "G", "R" };
  spec.DataX0 = 2;
  spec.DataY0 = 1;
  spec.DataX1 = 12;
  spec.DataY1 = 5;
  WriteExr(tmp.File("window.exr"), spec, [&](int x, int y, int k) { return value(x, y, 2 - k); });
  vs::LatLongImage img;
  std::string error;
  ASSERT_TRUE(vtkEnvironmentMapReader::ReadLatLong(tmp.File("window.exr").c_str(), img, error)) << error;
  ASSERT_EQ(img.Width, 16);
  ASSERT_EQ(img.Height, 8);
  for (int y = 0; y < 8; ++y)
  {
    for (int x = 0; x < 16; ++x)
    {
      const bool inside = x >= 2 && x <= 12 && y >= 1 && y <= 5;
      for (int k = 0; k < 3; ++k)
      {
        EXPECT_EQ(img.Pixel(x, y)[k], inside ? value(x, y, k) : 0.0f) << x << "," << y;
      }
    }
  }
  // No colour channel at all: an error naming the channels found.
  ExrSpec alpha;
  alpha.Channels = { "A" };
  WriteExr(tmp.File("alpha.exr"), alpha, [&](int x, int y, int) { return value(x, y, 0); });
  EXPECT_FALSE(vtkEnvironmentMapReader::ReadLatLong(tmp.File("alpha.exr").c_str(), img, error));
  EXPECT_NE(error.find("no R, G, B or Y channel (channels: A)"), std::string::npos) << error;
}

// Issue 13, item 9: a huge (or tiny) sun direction is a direction, normalised in double; it was an
// infinity in float and refused as "the sun direction must be a non-zero vector".
TEST(EnvironmentMapSource, HugeSunDirectionIsADirection)
{
  auto sunMap = [](double x, double y, double z, size_t* errors) {
    vtkNew<vtkEnvironmentMapSource> src;
    vtkNew<Messages> msgs;
    src->AddObserver(vtkCommand::ErrorEvent, msgs);
    src->SetOctahedralSize(32);
    src->SetTypeToSunDisk();
    src->SetSunDirection(x, y, z);
    src->SetSunAngularRadius(2.0);
    src->SetSunRadiance(100, 100, 100);
    src->Update();
    *errors = msgs->Errors.size();
    auto map = src->GetEnvironmentMap();
    return map ? map->Radiance : std::vector<float>();
  };
  size_t errors = 0;
  const std::vector<float> unit = sunMap(1, 0, 1, &errors);
  ASSERT_EQ(errors, 0u);
  ASSERT_FALSE(unit.empty());
  EXPECT_EQ(sunMap(1e300, 0, 1e300, &errors), unit);
  EXPECT_EQ(errors, 0u);
  EXPECT_EQ(sunMap(1e-300, 0, 1e-300, &errors), unit);
  EXPECT_EQ(errors, 0u);
  sunMap(0, 0, 0, &errors);
  EXPECT_EQ(errors, 1u) << "a zero direction is still an error";
}
