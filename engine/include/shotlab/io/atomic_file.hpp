// Files the program writes are replaced whole or not at all: the text goes to a new temporary file beside the target
// (a unique name), is flushed to disk, and is renamed over the target. A crash, a full disk or a bad path never
// leaves half a file, and a user's file is only replaced by a complete one; a symbolic link keeps pointing at its
// file (that file is replaced) and a replaced file keeps its permissions. A device or a pipe (/dev/stdout) is written
// to directly, its errors still reported.
#pragma once
#include <string>
#include <string_view>

namespace shotlab {

class AtomicFile {
 public:
  explicit AtomicFile(const std::string& path);  // throws InputError naming the path and the problem
  ~AtomicFile();                                 // not committed: the temporary file goes, the target stays as it was
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  void write(std::string_view text);  // throws InputError (a full disk, an I/O error)
  void finish();  // writes out and syncs to disk what is left; throws InputError. Files written together are all
                 // finished before any is committed, so that a failure leaves every target as it was.
  void commit();  // finishes if not yet done and renames over the target; throws InputError

 private:
  std::string path_, tmp_;
  int fd_ = -1;
  std::string buffer_;
  bool finished_ = false;
  void flush();
};

// The whole content in one go. Throws InputError.
void write_file_atomic(const std::string& path, std::string_view content);

}  // namespace shotlab
