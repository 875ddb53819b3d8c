// The CPU mirror (renderer/reference/shading_reference.h) as a filter, so that a numpy check
// (tests/reference/check_material_extensions.py) can hold it to the specification. One case a
// line on stdin, as glTF states the material (the ior to F0 conversion is the renderer's):
//   eye(3) position(3) normal(3) base(3) metallic roughness ior specularFactor specularColor(3)
//   unlit clearcoat clearcoatRoughness clearcoatNormal(3) sheenColor(3) sheenRoughness ambient
//   sunDirection(3) sunColor(3) anisotropyStrength anisotropyRotation tangent(4) geometricNormal(3)
//   anisotropyMapDirection(2) [iridescence iridescenceThickness iridescenceIor
//   [transmission thickness attenuationDistance attenuationColor(3) behind(3)]]
// (the optional three: KHR_materials_iridescence's strength, thickness in nm and film IOR;
// tests/reference/check_iridescence.py gives them; after them the optional nine:
// KHR_materials_transmission's and KHR_materials_volume's, and the radiance seen through the
// surface; tests/reference/check_transmission.py gives them)
// and one line "r g b" of shadeReference's linear radiance on stdout, in float's shortest exact form.
#include <algorithm>
#include <cstdio>
#include <iostream>
#include <sstream>
#include <string>

#include "renderer/reference/shading_reference.h"
#include "renderer/scene/material_features.h"

int main() {
    using namespace ml;
    glm::vec3 eye, base, specularColor, sunDirection, sunColor;
    SurfaceSample s;
    float ior, specularFactor, ambient, rotation;
    glm::vec4 tangent;
    glm::vec3 ng;
    glm::vec2 mapDirection;
    int unlit;
    for (std::string line; std::getline(std::cin, line);) {
        std::istringstream in(line);
        if (!(in >> eye.x >> eye.y >> eye.z >> s.position.x >> s.position.y >> s.position.z >> s.normal.x >>
           s.normal.y >> s.normal.z >> base.r >> base.g >> base.b >> s.metallic >> s.roughness >> ior >>
           specularFactor >> specularColor.r >> specularColor.g >> specularColor.b >> unlit >> s.clearcoat >>
           s.clearcoatRoughness >> s.clearcoatNormal.x >> s.clearcoatNormal.y >> s.clearcoatNormal.z >> s.sheenColor.r >>
           s.sheenColor.g >> s.sheenColor.b >> s.sheenRoughness >> ambient >>
           sunDirection.x >> sunDirection.y >> sunDirection.z >> sunColor.r >> sunColor.g >> sunColor.b >>
           s.anisotropyStrength >> rotation >> tangent.x >> tangent.y >> tangent.z >> tangent.w >> ng.x >> ng.y >> ng.z >>
           mapDirection.x >> mapDirection.y))
            continue;
        // KHR_materials_anisotropy's directions as glsl/include/material.glsl makes them.
        if (s.anisotropyStrength > 0.0f && !anisotropyDirections(ng, tangent, mapDirection, rotation, s.anisotropyT, s.anisotropyB))
            s.anisotropyStrength = 0.0f;
        if (!(in >> s.iridescence >> s.iridescenceThickness >> s.iridescenceIor)) s.iridescence = 0.0f;
        if (!(in >> s.transmission >> s.thickness >> s.attenuationDistance >> s.attenuationColor.r >> s.attenuationColor.g >>
              s.attenuationColor.b >> s.behind.r >> s.behind.g >> s.behind.b))
            s.transmission = 0.0f;
        s.baseColor = base;
        s.specularF0 = glm::min(dielectricF0(ior) * specularColor, glm::vec3(1.0f));  // as glsl/include/material.glsl
        s.specularWeight = specularFactor;
        s.unlit = unlit != 0;
        Light sun;
        sun.type = LightType::Directional;
        sun.direction = sunDirection;
        sun.color = sunColor;
        const glm::vec3 c = shadeReference(s, eye, {sun}, ambient);
        std::printf("%.9g %.9g %.9g\n", c.r, c.g, c.b);
    }
    return 0;
}
