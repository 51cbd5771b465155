#include "render/shading.h"

#include <algorithm>
#include <cmath>

namespace uvtk::render {

Vec4 headlightColour(const Lighting& l, const Vec3& eyeNormal) {
  const Vec3 toLight(0.0, 0.0, 1.0), halfway(0.0, 0.0, 1.0);
  const double nDotL = eyeNormal.dot(toLight);
  const double diffuse = std::max(nDotL, 0.0);
  const double specular = nDotL != 0.0 ? std::pow(std::max(eyeNormal.dot(halfway), 0.0), l.shininess) : 0.0;
  Vec4 c;
  // GL 4.6 compatibility eq. 12.2 with one light, no emission, attenuation and spot factor 1.
  c.head<3>() = (l.materialAmbient.cwiseProduct(l.modelAmbient) + l.materialAmbient.cwiseProduct(l.lightAmbient) +
                 diffuse * l.materialDiffuse.cwiseProduct(l.lightDiffuse) +
                 specular * l.materialSpecular.cwiseProduct(l.lightSpecular))
                    .head<3>();
  c.w() = l.materialDiffuse.w();
  return c.cwiseMax(0.0).cwiseMin(1.0);
}

bool readsFragmentColour(EnvMode mode) { return mode != EnvMode::Replace; }

}  // namespace uvtk::render
