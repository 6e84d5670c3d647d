#include "ui/files.hpp"

#include <algorithm>
#include <cstdlib>
#include <filesystem>

#include <pwd.h>
#include <unistd.h>

namespace shotlab {

namespace fs = std::filesystem;

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
    const auto ext = it->path().extension();
    if (folder || ext == ".json" || ext == ".csv") out.push_back({name, folder});
  }
  std::sort(out.begin(), out.end(), [](const DirEntry& a, const DirEntry& b) {
    return a.folder != b.folder ? a.folder : a.name < b.name;
  });
  return out;
}

std::string home_folder() {
  if (const char* home = std::getenv("HOME"); home && *home) return home;
  // HOME unset (a service, env -i): the account's own, looked up once (the dialogs ask every frame).
  static const std::string account = [] {
    const passwd* user = getpwuid(getuid());
    return std::string(user && user->pw_dir ? user->pw_dir : "");
  }();
  return account;
}

std::string typed_path(const std::string& typed, const std::string& dir) {
  const size_t from = typed.find_first_not_of(" \t"), to = typed.find_last_not_of(" \t");
  if (from == std::string::npos) return "";
  fs::path p = typed.substr(from, to - from + 1);
  if (p == "~" || p.string().rfind("~/", 0) == 0)
    if (const std::string home = home_folder(); !home.empty())
      p = fs::path(home) / p.string().substr(std::min<size_t>(2, p.string().size()));
  if (p.is_relative()) p = fs::path(dir) / p;
  p = p.lexically_normal();
  if (p.filename().empty() && p.has_relative_path()) p = p.parent_path();  // "/home/u/" is the folder "/home/u"
  return p.string();
}

std::string scene_file_path(const std::string& typed, const std::string& dir) {
  std::string path = typed_path(typed, dir);
  std::error_code ec;
  if (!path.empty() && fs::path(path).extension().empty() && !fs::is_directory(path, ec)) path += ".json";
  return path;
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

std::string user_folder(const std::vector<std::string>& recent, const std::string& presets_dir) {
  std::error_code ec;
  for (const std::string& r : recent) {
    const fs::path folder = fs::absolute(r, ec).parent_path();
    if (!ec && !inside(r, presets_dir) && fs::is_directory(folder, ec)) return folder.string();
  }
  if (const std::string home = home_folder(); !home.empty() && fs::is_directory(home, ec)) return home;
  return fs::current_path(ec).string();
}

}  // namespace shotlab
