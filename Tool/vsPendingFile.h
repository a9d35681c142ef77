// vsPendingFile.h — an output file written under a temporary name in its destination folder and
// renamed on Commit(); removed if never committed, so an error never leaves a partial output.
#ifndef vsPendingFile_h
#define vsPendingFile_h

#include <memory>
#include <string>
#include <vector>

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

  const std::string& DestinationPath() const { return this->Destination; }

private:
  friend void CommitAll(const std::vector<PendingFile*>& files);
  std::string Destination;
  std::string Temporary;
  bool Committed = false;
};

/** Commits a group of outputs all together or not at all: existing destinations are moved
 *  aside first, then every file is renamed into place; if any rename fails, the ones already
 *  renamed are removed, the previous files restored, and std::runtime_error names the failure. */
void CommitAll(const std::vector<PendingFile*>& files);

/** Throws std::runtime_error (starting with `option`) unless `destination` can be written
 *  as a PendingFile: its folder exists, it is not a directory or other non-regular file,
 *  and a temporary file can be created there. Call before the (slow) work. */
void CheckWritable(const std::string& option, const std::string& destination);
}

#endif
