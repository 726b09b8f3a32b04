// The schema of a light and a material object (CONTRACT 3), the one layer that case files,
// scene files (CONTRACT 7: "Lights and materials use the fields of section 3") and the
// renderer's scenes read them through, so that no two formats can drift apart.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "arealight/case.hpp"
#include "arealight/case_io.hpp"
#include "json_fields.hpp"

namespace arealight::io_detail {

// Reads one light object (a case's "light" value) into `out`, every error reported under
// `where` with its field named `prefix` + the light's own field ("light." in a case file,
// "" in a scene, whose lights are listed on their own). `extra`: further fields the
// caller's format allows there (a scene light's "intensity").
void read_light_object(Reporter& rep, const std::string& where, const std::string& prefix,
                       const nlohmann::json& light, const ValidationTolerances& tol, Light& out,
                       FieldNames extra = {});

// The same for a material object (a case's "material" value; a scene's adds "quality").
void read_material_object(Reporter& rep, const std::string& where, const std::string& prefix,
                          const nlohmann::json& material, Material& out, FieldNames extra = {});

// A point: 3 finite numbers of magnitude at most 1e15, under field `key` of `obj` (named
// `field` in messages); false after reporting why.
bool read_point(Reporter& rep, const std::string& where, const nlohmann::json& obj,
                const char* key, const std::string& field, Vec3& out);

// A direction: a point that is not the zero vector.
bool read_direction(Reporter& rep, const std::string& where, const nlohmann::json& obj,
                    const char* key, const std::string& field, Vec3& out);

}  // namespace arealight::io_detail
