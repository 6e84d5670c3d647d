// The scene format's plain fields, each spelled once with its check: the reader (scene_json.cpp) reads them and the
// writer (scene_write.cpp) writes them from these tables. Fields with their own rules are spelled in both.
#pragma once
#include <nlohmann/json.hpp>

#include "shotlab/io/json_reader.hpp"
#include "shotlab/material.hpp"
#include "shotlab/model.hpp"
#include "shotlab/table.hpp"

namespace shotlab {

// The table's optional dimensions (m), each with its check.
constexpr Field<TableSpec, double> kTableFields[] = {
    {"length", &TableSpec::length, &JsonNode::positive},
    {"width", &TableSpec::width, &JsonNode::positive},
    {"nose_height", &TableSpec::nose_height, &JsonNode::positive},
    {"ball_radius", &TableSpec::ball_radius, &JsonNode::positive},
    {"cushion_radius", &TableSpec::cushion_radius, &JsonNode::positive},
    {"corner_mouth", &TableSpec::corner_mouth, &JsonNode::positive},
    {"side_mouth", &TableSpec::side_mouth, &JsonNode::positive},
    {"pocket_radius", &TableSpec::pocket_radius, &JsonNode::positive},
    {"pocket_shelf", &TableSpec::pocket_shelf, &JsonNode::non_negative},
    {"jaw_length", &TableSpec::jaw_length, &JsonNode::non_negative},
    {"rail_width", &TableSpec::rail_width, &JsonNode::non_negative},
};

// A material's numbers (units in material.hpp).
constexpr Field<ContactMaterial, double> kMaterialNumbers[] = {
    {"stiffness", &ContactMaterial::stiffness, &JsonNode::positive},
    {"damping", &ContactMaterial::damping, &JsonNode::non_negative},
    {"exponent", &ContactMaterial::exponent, &JsonNode::positive},
    {"friction", &ContactMaterial::friction, &JsonNode::non_negative},
    {"friction_decay", &ContactMaterial::friction_decay, &JsonNode::non_negative},
    {"rolling_resistance", &ContactMaterial::rolling_resistance, &JsonNode::non_negative},
    {"spin_friction", &ContactMaterial::spin_friction, &JsonNode::non_negative},
    {"restitution_speed", &ContactMaterial::restitution_speed, &JsonNode::positive},
    {"contact_time", &ContactMaterial::contact_time, &JsonNode::non_negative},
};

// The model's options: numbers (units in model.hpp) and the solver switches.
constexpr Field<Options, double> kOptionNumbers[] = {
    {"friction_sharpness", &Options::friction_sharpness, &JsonNode::positive},
    {"friction_rate_limit", &Options::friction_rate_limit, &JsonNode::non_negative},
    {"rest_speed", &Options::rest_speed, &JsonNode::positive},
    {"contact_margin", &Options::contact_margin, &JsonNode::positive},
    {"sleep_time", &Options::sleep_time, &JsonNode::non_negative},
};
constexpr Field<Options, bool> kOptionSwitches[] = {
    {"rolling_regime", &Options::rolling_regime, &JsonNode::boolean},
    {"sliding_regime", &Options::sliding_regime, &JsonNode::boolean},
    {"swing_regime", &Options::swing_regime, &JsonNode::boolean},
    {"flight_regime", &Options::flight_regime, &JsonNode::boolean},
    {"bounce_regime", &Options::bounce_regime, &JsonNode::boolean},
    {"islands", &Options::islands, &JsonNode::boolean},
};

// Writes every field of a table into `out`, as read_fields reads them.
template <class S, class T, size_t N>
void write_fields(nlohmann::json& out, const S& s, const Field<S, T> (&fields)[N]) {
  for (const Field<S, T>& f : fields) out[f.key] = s.*f.member;
}

}  // namespace shotlab
