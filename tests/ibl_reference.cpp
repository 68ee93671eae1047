#include "tests/ibl_reference.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

namespace pbr::test {

std::vector<glm::vec4> readCubemapLevel(const Cubemap& cubemap, int level) {
  const int size = cubemap.faceSize(level);
  std::vector<glm::vec4> texels(size_t{6} * size * size);
  glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  glGetTextureImage(cubemap.id(), level, GL_RGBA, GL_FLOAT, static_cast<GLsizei>(texels.size() * sizeof(glm::vec4)),
                    texels.data());
  checkGlError("readCubemapLevel");
  return texels;
}

CubeCoord cubeCoord(const glm::dvec3& d) {
  const glm::dvec3 a = glm::abs(d);
  double sc, tc, ma;
  int face;
  if (a.x >= a.y && a.x >= a.z) {
    face = d.x > 0 ? 0 : 1;
    sc = d.x > 0 ? -d.z : d.z;
    tc = -d.y;
    ma = a.x;
  } else if (a.y >= a.z) {
    face = d.y > 0 ? 2 : 3;
    sc = d.x;
    tc = d.y > 0 ? d.z : -d.z;
    ma = a.y;
  } else {
    face = d.z > 0 ? 4 : 5;
    sc = d.z > 0 ? d.x : -d.x;
    tc = -d.y;
    ma = a.z;
  }
  return {face, glm::dvec2(0.5 * (sc / ma + 1.0), 0.5 * (tc / ma + 1.0))};
}

glm::dvec3 cubeTexelDirection(int face, int x, int y, int size) {
  const double sc = 2.0 * (x + 0.5) / size - 1.0, tc = 2.0 * (y + 0.5) / size - 1.0;
  glm::dvec3 d;
  switch (face) {
    case 0: d = {1.0, -tc, -sc}; break;
    case 1: d = {-1.0, -tc, sc}; break;
    case 2: d = {sc, 1.0, tc}; break;
    case 3: d = {sc, -1.0, -tc}; break;
    case 4: d = {sc, -tc, 1.0}; break;
    default: d = {-sc, -tc, -1.0}; break;
  }
  return glm::normalize(d);
}

double cubeTexelSolidAngle(int x, int y, int size) {
  const auto area = [](double u, double v) { return std::atan2(u * v, std::sqrt(u * u + v * v + 1.0)); };
  const double x0 = 2.0 * x / size - 1.0, x1 = 2.0 * (x + 1) / size - 1.0;
  const double y0 = 2.0 * y / size - 1.0, y1 = 2.0 * (y + 1) / size - 1.0;
  return area(x0, y0) - area(x0, y1) - area(x1, y0) + area(x1, y1);
}

CubeTexels cubeTexels(const Cubemap& cubemap, int level) {
  const std::vector<glm::vec4> texels = readCubemapLevel(cubemap, level);
  CubeTexels out;
  out.size = cubemap.faceSize(level);
  for (int face = 0; face < 6; ++face) {
    for (int y = 0; y < out.size; ++y) {
      for (int x = 0; x < out.size; ++x) {
        out.radiance.emplace_back(texels[(static_cast<size_t>(face) * out.size + y) * out.size + x]);
        out.direction.push_back(cubeTexelDirection(face, x, y, out.size));
        out.solidAngle.push_back(cubeTexelSolidAngle(x, y, out.size));
      }
    }
  }
  return out;
}

glm::dvec3 totalEnergy(const CubeTexels& texels) {
  glm::dvec3 sum(0.0);
  for (size_t i = 0; i < texels.radiance.size(); ++i) sum += texels.radiance[i] * texels.solidAngle[i];
  return sum;
}

glm::dvec3 bruteForceIrradiance(const CubeTexels& texels, const glm::dvec3& n) {
  glm::dvec3 sum(0.0);
  for (size_t i = 0; i < texels.radiance.size(); ++i) {
    const double cosine = glm::dot(n, texels.direction[i]);
    if (cosine > 0.0) sum += texels.radiance[i] * (cosine * texels.solidAngle[i]);
  }
  return sum;
}

std::vector<glm::dvec3> fibonacciSphere(int n) {
  std::vector<glm::dvec3> points;
  const double golden = kPi * (3.0 - std::sqrt(5.0));
  for (int i = 0; i < n; ++i) {
    const double y = 1.0 - (2.0 * i + 1.0) / n;
    const double r = std::sqrt(std::max(0.0, 1.0 - y * y));
    points.emplace_back(r * std::cos(golden * i), y, r * std::sin(golden * i));
  }
  return points;
}

IblBlock readIblBlock(const Buffer& buffer) {
  IblBlock block{};
  glGetNamedBufferSubData(buffer.id(), 0, sizeof(IblBlock), &block);
  checkGlError("readIblBlock");
  return block;
}

std::vector<glm::vec2> readDfgTable(const Texture& table) {
  std::vector<glm::vec2> texels(static_cast<size_t>(table.width()) * table.height());
  glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  glGetTextureImage(table.id(), 0, GL_RG, GL_FLOAT, static_cast<GLsizei>(texels.size() * sizeof(glm::vec2)),
                    texels.data());
  checkGlError("readDfgTable");
  return texels;
}

double ggxD(double cosThetaH, double a) {
  const double c2 = cosThetaH * cosThetaH;
  const double tan2 = (1.0 - c2) / c2;
  const double k = a * a + tan2;
  return a * a / (kPi * c2 * c2 * k * k);
}

double smithVisibility(double NoV, double NoL, double a) {
  const auto lambda = [a](double c) {
    const double tan2 = (1.0 - c * c) / (c * c);
    return 0.5 * (std::sqrt(1.0 + a * a * tan2) - 1.0);
  };
  return 1.0 / ((1.0 + lambda(NoV) + lambda(NoL)) * 4.0 * NoL * NoV);
}

double alphaFromRoughness(double roughness) {
  const double r = std::max(roughness, 0.045);
  return r * r;
}

glm::dvec2 referenceDfg(double NoV, double roughness) {
  const double a = alphaFromRoughness(roughness);
  const glm::dvec3 v(std::sqrt(1.0 - NoV * NoV), 0.0, NoV);
  // theta_h = a sinh(t s) puts nodes hundredths of `a` apart under a narrow peak and still reaches the horizon.
  constexpr int kTheta = 512, kPhi = 256;
  const double s = std::asinh(kPi / 2.0 / a);
  glm::dvec2 sum(0.0);
  for (int i = 0; i < kTheta; ++i) {
    const double t = (i + 0.5) / kTheta;
    const double theta = a * std::sinh(t * s);
    const double dTheta = a * s * std::cosh(t * s) / kTheta;
    const double cosT = std::cos(theta), sinT = std::sin(theta);
    const double d = ggxD(cosT, a);
    for (int j = 0; j < kPhi; ++j) {
      const double phi = 2.0 * kPi * (j + 0.5) / kPhi;
      const glm::dvec3 h(sinT * std::cos(phi), sinT * std::sin(phi), cosT);
      const double VoH = glm::dot(v, h);
      const double NoL = 2.0 * VoH * cosT - NoV;
      if (VoH <= 0.0 || NoL <= 0.0) continue;
      // dl = 4 (v.h) dh turns the integral over l into one over the half vector.
      const double w = d * smithVisibility(NoV, NoL, a) * NoL * 4.0 * VoH * sinT * dTheta * (2.0 * kPi / kPhi);
      const double fc = std::pow(1.0 - VoH, 5.0);
      sum += glm::dvec2(1.0 - fc, fc) * w;
    }
  }
  return sum;
}

}  // namespace pbr::test
