// vsPendingFile.h — an output file written under a temporary name in its destination folder and
// renamed on Commit(); removed if never committed, so an error never leaves a partial output.
#ifndef vsPendingFile_h
#define vsPendingFile_h

#include <string>

namespace vstool
{
class PendingFile
{
public:
  explicit PendingFile(const std::string& destination);
  PendingFile(const PendingFile&) = delete;
  PendingFile& operator=(const PendingFile&) = delete;
  ~PendingFile();
  const std::string& Path() const { return this->Temporary; }
  /** Renames the file to its destination; throws std::runtime_error if that fails. */
  void Commit();

private:
  std::string Destination;
  std::string Temporary;
  bool Committed = false;
};
}

#endif
