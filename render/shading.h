// What a fragment's colour is made of in OpenGL's fixed-function pipeline: the lighting equation
// at the vertices (a head-light, Blinn-Phong) and the texture environment that combines the
// fragment's colour with the texel.
#pragma once

#include "core/math.h"

namespace uvtk::render {

enum class EnvMode { Replace, Modulate, Decal, Blend };

// GL_LIGHT0 as a head-light (position (0, 0, 1, 0) given under an identity modelview: a
// directional light along the view direction), an infinite viewer, one-sided lighting unless
// twoSided (GL_LIGHT_MODEL_TWO_SIDE: a back face, clockwise in the window, is lit with its normal
// negated, the back material being the front's, so that an open or inward-wound mesh seen from
// behind reads as its front does; GL 4.6 compatibility §12.2.1). The light
// keeps GL's defaults; the material keeps GL's ambient and diffuse defaults and adds a white
// specular highlight (GL's default specular is black, which would not be Blinn-Phong at all).
struct Lighting {
  Vec4 modelAmbient = Vec4(0.2, 0.2, 0.2, 1.0);     // GL_LIGHT_MODEL_AMBIENT
  Vec4 lightAmbient = Vec4(0.0, 0.0, 0.0, 1.0);     // GL_LIGHT0 GL_AMBIENT
  Vec4 lightDiffuse = Vec4(1.0, 1.0, 1.0, 1.0);     // GL_LIGHT0 GL_DIFFUSE
  Vec4 lightSpecular = Vec4(1.0, 1.0, 1.0, 1.0);    // GL_LIGHT0 GL_SPECULAR
  Vec4 materialAmbient = Vec4(0.2, 0.2, 0.2, 1.0);  // GL_AMBIENT
  Vec4 materialDiffuse = Vec4(0.8, 0.8, 0.8, 1.0);  // GL_DIFFUSE
  Vec4 materialSpecular = Vec4(0.5, 0.5, 0.5, 1.0); // GL_SPECULAR
  double shininess = 32.0;                          // GL_SHININESS
  bool twoSided = false;                            // GL_LIGHT_MODEL_TWO_SIDE
};

// GL 4.6 compatibility §12.2.1 for one light at infinity along +z of eye space and an infinite
// viewer (h = (0, 0, 1)): a_cm a_cs + a_cm a_cl + max(n.l, 0) d_cm d_cl + f max(n.h, 0)^s s_cm s_cl,
// f = 1 where n.l != 0; clamped to [0, 1]; alpha = the diffuse material's. `eyeNormal` has unit
// length (or is zero: then only the ambient terms remain).
Vec4 headlightColour(const Lighting& lighting, const Vec3& eyeNormal);

// The texture environment for an RGBA texel (GL 4.6 compatibility §16.1, table 16.1):
// REPLACE Ct, At; MODULATE Cf Ct, Af At; DECAL Cf (1 - At) + Ct At, Af; BLEND Cf (1 - Ct) + Cc Ct,
// Af At. An RGB or luminance texture has At = 1, which gives GL's RGB rows of the table. Inline:
// every shaded fragment goes through it.
inline Vec4 textureEnvironment(EnvMode mode, const Vec4& f, const Vec4& t, const Vec4& c) {
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

// Whether a mode reads the fragment's colour (so lighting must be computed).
bool readsFragmentColour(EnvMode mode);

}  // namespace uvtk::render
