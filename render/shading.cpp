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

Vec4 textureEnvironment(EnvMode mode, const Vec4& f, const Vec4& t, const Vec4& c) {
  const Vec3 cf = f.head<3>(), ct = t.head<3>(), cc = c.head<3>();
  switch (mode) {  // GL 4.6 compatibility table 16.1, RGBA base format
    case EnvMode::Replace: return t;
    case EnvMode::Modulate: return f.cwiseProduct(t);
    case EnvMode::Decal: {
      Vec4 out;
      out << cf * (1.0 - t.w()) + ct * t.w(), f.w();
      return out;
    }
    case EnvMode::Blend: {
      Vec4 out;
      out << cf.cwiseProduct(Vec3::Ones() - ct) + cc.cwiseProduct(ct), f.w() * t.w();
      return out;
    }
  }
  return t;
}

bool readsFragmentColour(EnvMode mode) { return mode != EnvMode::Replace; }

}  // namespace uvtk::render
