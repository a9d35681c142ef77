// Writes the seed corpus of fuzz_volume_file: tiny valid volumes written by VTK's own writers
// (NIfTI, gzipped NIfTI, MetaImage) and a hand-written NRRD, each prefixed by the format byte
// FuzzVolumeFile.cxx reads (0 .nii, 1 .nii.gz, 2 .mha, 3 .nrrd). Usage: vissweep_fuzz_volume_seeds DIR
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkMetaImageWriter.h"
#include "vtkNIFTIImageWriter.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkUnsignedCharArray.h"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace
{
vtkSmartPointer<vtkImageData> Volume(int nx, int ny, int nz, bool bytes)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(nx, ny, nz);
  image->SetSpacing(1.0, 0.5, 2.0);
  image->SetOrigin(-1.0, 0.0, 3.0);
  vtkSmartPointer<vtkDataArray> a;
  if (bytes)
  {
    a = vtkSmartPointer<vtkUnsignedCharArray>::New();
  }
  else
  {
    a = vtkSmartPointer<vtkFloatArray>::New();
  }
  a->SetNumberOfTuples(vtkIdType(nx) * ny * nz);
  for (vtkIdType i = 0; i < a->GetNumberOfTuples(); ++i)
  {
    a->SetTuple1(i, double(i % 7));
  }
  image->GetPointData()->SetScalars(a);
  return image;
}

// Prefixes the file at `path` with the format byte and moves it to `seed`.
void Prefix(const fs::path& path, const fs::path& seed, char format)
{
  std::vector<char> b;
  {
    std::ifstream in(path, std::ios::binary);
    b.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  std::ofstream out(seed, std::ios::binary);
  out.put(format);
  out.write(b.data(), std::streamsize(b.size()));
  fs::remove(path);
}
}

int main(int argc, char** argv)
{
  if (argc != 2)
  {
    std::fprintf(stderr, "usage: %s SEED_DIR\n", argv[0]);
    return 2;
  }
  const fs::path dir(argv[1]);
  fs::create_directories(dir);
  const fs::path scratch = dir / "scratch";
  fs::create_directories(scratch);
  struct Case
  {
    const char* name;
    int nx, ny, nz;
    bool bytes;
  };
  for (const Case& c : { Case{ "float_4x3x2", 4, 3, 2, false }, Case{ "uchar_2x2x5", 2, 2, 5, true } })
  {
    for (const char* ext : { ".nii", ".nii.gz" })
    {
      vtkNew<vtkNIFTIImageWriter> w;
      const fs::path f = scratch / (std::string(c.name) + ext);
      w->SetFileName(f.string().c_str());
      w->SetInputData(Volume(c.nx, c.ny, c.nz, c.bytes));
      w->Write();
      Prefix(f, dir / (std::string(c.name) + ext), std::string(ext) == ".nii" ? 0 : 1);
    }
    for (bool compressed : { false, true })
    {
      vtkNew<vtkMetaImageWriter> w;
      const fs::path f = scratch / (std::string(c.name) + ".mha");
      w->SetFileName(f.string().c_str());
      w->SetCompression(compressed);
      w->SetInputData(Volume(c.nx, c.ny, c.nz, c.bytes));
      w->Write();
      Prefix(f, dir / (std::string(c.name) + (compressed ? "_zlib" : "") + ".mha"), 2);
    }
    std::string nrrd = "NRRD0004\ntype: " + std::string(c.bytes ? "uchar" : "float") + "\ndimension: 3\nsizes: " +
      std::to_string(c.nx) + " " + std::to_string(c.ny) + " " + std::to_string(c.nz) +
      "\nencoding: raw\nendian: little\nspacings: 1 0.5 2\nspace origin: (-1,0,3)\n\n";
    const size_t n = size_t(c.nx) * c.ny * c.nz;
    for (size_t i = 0; i < n; ++i)
    {
      if (c.bytes)
      {
        nrrd.push_back(char(i % 7));
      }
      else
      {
        const float v = float(i % 7);
        nrrd.append(reinterpret_cast<const char*>(&v), sizeof(v));
      }
    }
    std::ofstream out(dir / (std::string(c.name) + ".nrrd"), std::ios::binary);
    out.put(3);
    out.write(nrrd.data(), std::streamsize(nrrd.size()));
  }
  fs::remove_all(scratch);
  return 0;
}
