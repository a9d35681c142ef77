#include "vsPendingFile.h"

#include <unistd.h>

#include <filesystem>
#include <fstream>
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

void CommitAll(const std::vector<PendingFile*>& files)
{
  struct Step
  {
    PendingFile* File;
    std::string Backup; // where the previous destination went (empty: there was none)
    bool Renamed = false;
  };
  std::vector<Step> steps;
  for (PendingFile* f : files)
  {
    steps.push_back({ f, std::string(), false });
  }
  auto rollBack = [&steps]() {
    std::error_code ignored;
    for (auto it = steps.rbegin(); it != steps.rend(); ++it)
    {
      if (it->Renamed)
      {
        fs::rename(it->File->Destination, it->File->Temporary, ignored);
      }
      if (!it->Backup.empty())
      {
        fs::rename(it->Backup, it->File->Destination, ignored);
      }
    }
  };
  std::string failure;
  for (Step& step : steps)
  {
    std::error_code ec;
    const fs::path d(step.File->Destination);
    const fs::file_status st = fs::symlink_status(d, ec);
    if (fs::exists(st) && !fs::is_regular_file(st) && !fs::is_symlink(st))
    {
      // Only a file (or a link, not its target) is ever replaced: a folder or device that appeared at
      // the path after CheckWritable is left as it is, and nothing is written.
      failure = "'" + d.string() + "' " + (fs::is_directory(st) ? "is a directory" : "is not a regular file") +
        "; it is not replaced";
      break;
    }
    if (fs::exists(st))
    {
      const fs::path dir = d.has_parent_path() ? d.parent_path() : fs::path(".");
      step.Backup = (dir / ("." + d.filename().string() + ".previous-" + std::to_string(::getpid()))).string();
      fs::rename(d, step.Backup, ec);
      if (ec)
      {
        failure = "cannot move the existing '" + d.string() + "' aside: " + ec.message();
        step.Backup.clear();
        break;
      }
    }
  }
  for (Step& step : steps)
  {
    if (!failure.empty())
    {
      break;
    }
    std::error_code ec;
    fs::rename(step.File->Temporary, step.File->Destination, ec);
    if (ec)
    {
      failure = "cannot rename '" + step.File->Temporary + "' to '" + step.File->Destination + "': " + ec.message();
      break;
    }
    step.Renamed = true;
  }
  if (!failure.empty())
  {
    rollBack();
    throw std::runtime_error(failure + " (no output was written)");
  }
  for (Step& step : steps)
  {
    std::error_code ignored;
    if (!step.Backup.empty())
    {
      fs::remove(step.Backup, ignored); // a file or a link: never a folder (see above)
    }
    step.File->Committed = true;
  }
}

void CheckWritable(const std::string& option, const std::string& destination)
{
  const fs::path d(destination);
  const fs::path dir = d.has_parent_path() ? d.parent_path() : fs::path(".");
  std::error_code ec;
  if (!fs::is_directory(dir, ec))
  {
    throw std::runtime_error(option + " " + destination + ": folder '" + dir.string() + "' does not exist");
  }
  const fs::file_status st = fs::status(d, ec);
  if (fs::exists(st) && !fs::is_regular_file(st))
  {
    throw std::runtime_error(option + " " + destination + ": " +
      (fs::is_directory(st) ? "is a directory" : "exists and is not a regular file") + "; give a file name");
  }
  PendingFile probe(destination);
  std::ofstream out(probe.Path());
  if (!out)
  {
    throw std::runtime_error(option + " " + destination + ": cannot create a file in folder '" + dir.string() + "'");
  }
}
}
