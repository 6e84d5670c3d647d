#include "ui/files.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <stdexcept>

namespace shotlab {

namespace fs = std::filesystem;

namespace {
std::runtime_error failure(const std::string& path, const std::string& what) {
  return std::runtime_error(path + ": " + what + " (" + std::strerror(errno) + ")");
}
}  // namespace

void write_file_atomic(const std::string& requested, const std::string& content) {
  // A symbolic link keeps pointing at its file: the file it points to is what gets replaced.
  std::error_code ec;
  const std::string path = fs::is_symlink(requested, ec) ? fs::weakly_canonical(requested, ec).string() : requested;
  const fs::path target(path);
  const fs::path dir = target.has_parent_path() ? target.parent_path() : fs::path(".");
  std::string tmp = (dir / ("." + target.filename().string() + ".XXXXXX")).string();
  const int fd = mkstemp(tmp.data());
  if (fd < 0) throw failure(path, "cannot create a temporary file beside it");
  size_t done = 0;
  while (done < content.size()) {
    const ssize_t n = ::write(fd, content.data() + done, content.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      const auto err = failure(path, "cannot write");
      ::close(fd), ::unlink(tmp.c_str());
      throw err;
    }
    done += static_cast<size_t>(n);
  }
  if (::fsync(fd) != 0 || ::close(fd) != 0) {
    const auto err = failure(path, "cannot write to disk");
    ::unlink(tmp.c_str());
    throw err;
  }
  // A replaced file keeps its permissions; a new one gets the usual rw-r--r-- (less what the umask takes).
  struct stat old {};
  if (::stat(path.c_str(), &old) == 0) ::chmod(tmp.c_str(), old.st_mode & 07777);
  else {
    const mode_t mask = ::umask(0);
    ::umask(mask);
    ::chmod(tmp.c_str(), 0666 & ~mask);
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    const auto err = failure(path, "cannot replace the file");
    ::unlink(tmp.c_str());
    throw err;
  }
}

std::string unique_path(const std::string& dir, const std::string& stem, const std::string& ext) {
  std::string clean;
  for (char c : stem) clean += std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' ? c : '-';
  if (clean.empty()) clean = "shotlab";
  for (int n = 1;; ++n) {
    const fs::path p = fs::path(dir.empty() ? "." : dir) / (clean + "-" + std::to_string(n) + "." + ext);
    std::error_code ec;
    if (!fs::exists(p, ec)) return p.string();
  }
}

std::vector<DirEntry> list_scene_dir(const std::string& dir) {
  std::vector<DirEntry> out;
  std::error_code ec;
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    if (name.empty() || name[0] == '.') continue;
    std::error_code e2;
    const bool folder = it->is_directory(e2);
    if (folder || it->path().extension() == ".json") out.push_back({name, folder});
  }
  std::sort(out.begin(), out.end(), [](const DirEntry& a, const DirEntry& b) {
    return a.folder != b.folder ? a.folder : a.name < b.name;
  });
  return out;
}

bool inside(const std::string& path, const std::string& dir) {
  std::error_code ec;
  const fs::path p = fs::weakly_canonical(path, ec);
  fs::path d = fs::weakly_canonical(dir, ec);
  if (ec) return false;
  if (d.filename().empty()) d = d.parent_path();  // "presets/" ends in an empty element
  auto [a, b] = std::mismatch(d.begin(), d.end(), p.begin(), p.end());
  return a == d.end();
}

}  // namespace shotlab
