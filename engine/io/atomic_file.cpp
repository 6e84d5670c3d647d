#include "shotlab/io/atomic_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include "shotlab/io/json_reader.hpp"

namespace shotlab {

namespace fs = std::filesystem;

namespace {

constexpr size_t kBufferBytes = 1 << 16;

InputError failure(const std::string& path, const std::string& what) {
  return InputError(path + ": " + what + " (" + std::strerror(errno) + ")");
}

}  // namespace

AtomicFile::AtomicFile(const std::string& requested) {
  std::error_code ec;
  const fs::file_status status = fs::status(requested, ec);  // of what a link points to
  if (fs::is_directory(status)) {
    errno = EISDIR;
    throw failure(requested, "cannot write the file");
  }
  if (fs::exists(status) && !fs::is_regular_file(status)) {  // a device or a pipe (/dev/stdout): write to it
    path_ = requested;
    fd_ = ::open(path_.c_str(), O_WRONLY | O_TRUNC);
    if (fd_ < 0) throw failure(path_, "cannot write the file");
    return;
  }
  path_ = fs::is_symlink(requested, ec) ? fs::weakly_canonical(requested, ec).string() : requested;
  if (path_.empty()) path_ = requested;
  const fs::path target(path_);
  const fs::path dir = target.has_parent_path() ? target.parent_path() : fs::path(".");
  std::string name = ".";  // hidden, unique: ".scene.json.a1B2c3"
  name += target.filename().string();
  name += ".XXXXXX";
  tmp_ = (dir / name).string();
  fd_ = mkstemp(tmp_.data());
  if (fd_ < 0) throw failure(path_, "cannot create a temporary file beside it");
}

AtomicFile::~AtomicFile() {
  if (fd_ < 0) return;
  ::close(fd_);
  if (!tmp_.empty()) ::unlink(tmp_.c_str());
}

void AtomicFile::write(std::string_view text) {
  buffer_.append(text);
  if (buffer_.size() >= kBufferBytes) flush();
}

void AtomicFile::flush() {
  size_t done = 0;
  while (done < buffer_.size()) {
    const ssize_t n = ::write(fd_, buffer_.data() + done, buffer_.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) throw failure(path_, "cannot write");
    done += static_cast<size_t>(n);
  }
  buffer_.clear();
}

void AtomicFile::finish() {
  flush();
  if (!tmp_.empty() && ::fsync(fd_) != 0) throw failure(path_, "cannot write to disk");
  finished_ = true;
}

void AtomicFile::commit() {
  if (!finished_) finish();
  if (tmp_.empty()) {  // written in place (a device or a pipe)
    const int fd = fd_;
    fd_ = -1;
    if (::close(fd) != 0) throw failure(path_, "cannot write");
    return;
  }
  const int fd = fd_;
  fd_ = -1;
  if (::close(fd) != 0) {
    const InputError err = failure(path_, "cannot write to disk");
    ::unlink(tmp_.c_str());
    throw err;
  }
  // A replaced file keeps its permissions; a new one gets the usual rw-r--r-- (less what the umask takes).
  struct stat old {};
  if (::stat(path_.c_str(), &old) == 0) {
    ::chmod(tmp_.c_str(), old.st_mode & 07777);
  } else {
    const mode_t mask = ::umask(0);
    ::umask(mask);
    ::chmod(tmp_.c_str(), 0666 & ~mask);
  }
  if (std::rename(tmp_.c_str(), path_.c_str()) != 0) {
    const InputError err = failure(path_, "cannot replace the file");
    ::unlink(tmp_.c_str());
    throw err;
  }
}

void write_file_atomic(const std::string& path, std::string_view content) {
  AtomicFile f(path);
  f.write(content);
  f.commit();
}

}  // namespace shotlab
