#include "rtpro/scene/principled_material.h"

#include "yaml_material_fields.h"

namespace rtpro {

namespace {

// A length above 0 in each channel of `subsurface_radius`, and of `subsurface_scale`: a radius of
// 0 would be a walk that never leaves the entry point (Cycles makes such channels diffuse; a
// scene asks for that with a smaller `subsurface` weight).
void read_subsurface(const MappingReader& material, PrincipledParams& params) {
  read_unit(material, "subsurface", params.subsurface);
  if (const YamlNode* node = material.optional("subsurface_radius")) {
    params.subsurface_radius = read_vec3(*node, material.field("subsurface_radius"));
    const Color& r = params.subsurface_radius;
    if (!(r.x > 0.0f && r.y > 0.0f && r.z > 0.0f))
      fail_at(*node, material.field("subsurface_radius") + " must be above 0 in each channel");
  }
  if (const YamlNode* node = material.optional("subsurface_scale")) {
    params.subsurface_scale = read_non_negative(*node, material.field("subsurface_scale"));
    if (!(params.subsurface_scale > 0.0f)) fail_at(*node, material.field("subsurface_scale") + " must be above 0");
  }
  if (const YamlNode* node = material.optional("subsurface_anisotropy")) {
    params.subsurface_anisotropy = read_non_negative(*node, material.field("subsurface_anisotropy"));
    if (params.subsurface_anisotropy > 0.9f)
      fail_at(*node,
              material.field("subsurface_anisotropy") + " must be from 0 to 0.9, got " + std::string(node->scalar()));
  }
  if (const YamlNode* node = material.optional("subsurface_method"))
    params.subsurface_method =
        read_keyword<SubsurfaceMethod>(*node, material.field("subsurface_method"),
                                       {{"random_walk", SubsurfaceMethod::kRandomWalk},
                                        {"random_walk_fixed_radius", SubsurfaceMethod::kRandomWalkFixedRadius}});
}

}  // namespace

std::vector<std::string_view> material_keys(const PrincipledParams&) {
  return {"roughness",        "ior",
          "metalness",        "specular_weight",
          "specular_color",   "transmission_weight",
          "coat_weight",      "coat_roughness",
          "fuzz_color",       "fuzz_roughness",
          "subsurface",       "subsurface_radius",
          "subsurface_scale", "subsurface_anisotropy",
          "subsurface_method"};
}

// Its weights and colours, each from 0 to 1.
void read_material_params(const MappingReader& material, PrincipledParams& params) {
  read_roughness(material, params.roughness);
  read_unit(material, "metalness", params.metalness);
  read_unit(material, "specular_weight", params.specular_weight);
  read_unit_color(material, "specular_color", params.specular_color);
  read_unit(material, "transmission_weight", params.transmission_weight);
  read_unit(material, "coat_weight", params.coat_weight);
  read_unit(material, "coat_roughness", params.coat_roughness);
  read_unit_color(material, "fuzz_color", params.fuzz_color);
  read_unit(material, "fuzz_roughness", params.fuzz_roughness);
  read_ior(material, params.ior);
  read_subsurface(material, params);
}

}  // namespace rtpro
