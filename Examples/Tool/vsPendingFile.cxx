#include "vsPendingFile.h"

#include <unistd.h>

#include <filesystem>
#include <stdexcept>
#include <system_error>

namespace vstool
{
namespace fs = std::filesystem;

PendingFile::PendingFile(const std::string& destination)
  : Destination(destination)
{
  fs::path d(destination);
  fs::path dir = d.has_parent_path() ? d.parent_path() : fs::path(".");
  this->Temporary =
    (dir / ("." + d.filename().string() + ".partial-" + std::to_string(::getpid()) + d.extension().string())).string();
}

PendingFile::~PendingFile()
{
  if (!this->Committed)
  {
    std::error_code ec;
    fs::remove(this->Temporary, ec);
  }
}

void PendingFile::Commit()
{
  std::error_code ec;
  fs::rename(this->Temporary, this->Destination, ec);
  if (ec)
  {
    throw std::runtime_error("cannot rename '" + this->Temporary + "' to '" + this->Destination + "': " + ec.message());
  }
  this->Committed = true;
}
}
