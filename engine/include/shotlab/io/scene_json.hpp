// Scene files: JSON, documented field by field in docs/scene-format.md. Conventions: SI units, y up, bed at y = 0;
// angles in the file are degrees (fields end in _deg).
#pragma once
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "shotlab/scene.hpp"
#include "shotlab/io/json_reader.hpp"

namespace shotlab {

inline constexpr size_t kMaxSceneBytes = size_t{16} << 20;  // a scene file larger than this is refused

// Reads a scene file, applies PATH=VALUE overrides (see apply_override), and parses it. Throws InputError naming
// the file, the field and the problem.
Scene load_scene(const std::string& path, const std::vector<std::string>& overrides = {});

// A scene file's text, refused (InputError) when it is a folder, unreadable or larger than kMaxSceneBytes.
std::string read_scene_file(const std::string& path);

// Parses JSON text; a syntax error, a number that overflows, nesting deeper than kMaxJsonDepth or a key given twice
// in one object becomes an InputError naming `source` (and the field).
inline constexpr int kMaxJsonDepth = 64;  // nesting levels a document may have (scene files need 4)
nlohmann::json parse_json_text(const std::string& text, const std::string& source);

// Parses a scene document; `source` names it in error messages.
Scene parse_scene(const nlohmann::json& doc, const std::string& source);

// "materials.ball_cloth.friction=0.3", "balls[0].velocity=[1,0,0]", "balls.cue.velocity=[1,0,0]" (an array element
// by its "id"), "integrator.method=rk4". VALUE is JSON; a bare word is taken as a string. Throws InputError.
void apply_override(nlohmann::json& doc, const std::string& assignment);

// The scene as a document that parse_scene reads back to the same scene (every field explicit).
nlohmann::json scene_to_json(const Scene& scene);

// Writes the scene atomically (atomic_file.hpp): a failed write leaves the old file as it was. Throws InputError.
void save_scene(const std::string& path, const Scene& scene);

}  // namespace shotlab
