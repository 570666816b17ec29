// SPDX-License-Identifier: BSD-3-Clause
// Mesolight relief: irradiance from a grid of SH9 radiance probes over the relief's texture
// (e.g. a virtual light field's light at the surface), evaluated at the relief's perturbed
// normal: E(n) = sum_lm A_l L_lm Y_lm(n) with Ramamoorthi and Hanrahan's constants ("An
// efficient representation for irradiance environment maps", eq. 8 and 12), the real SH basis
// of filters/Lighting (EnvironmentMaps.h) in world coordinates.
//
// The texture (vtkIrradianceProbesTexture) is Nu x 9 Nv: coefficient k of every probe in the
// rows [k Nv, (k + 1) Nv). A linear fetch inside that block interpolates the coefficient
// bilinearly between the four nearest probes; the fetch is clamped to the block's texel centres,
// which clamps at the grid's border (probe (i, j) stands at ((i + 1/2) / Nu, (j + 1/2) / Nv)).

uniform sampler2D mlIrradianceProbes;
uniform vec2 mlProbeGrid; // (Nu, Nv)

// Irradiance at texture coordinates uv for the unit world normal n, clamped at 0 (to be
// multiplied by albedo / pi).
vec3 mlProbeIrradiance(vec2 uv, vec3 n)
{
  vec2 probe = clamp(uv * mlProbeGrid, vec2(0.5), mlProbeGrid - vec2(0.5));
  float s = probe.x / mlProbeGrid.x;
  float rows = 9.0 * mlProbeGrid.y;
  // A_l Y_lm(n) per coefficient, in the order of SH9 (Y00, Y1-1, Y10, Y11, Y2-2, Y2-1, Y20, Y21,
  // Y22): A_0 = pi, A_1 = 2 pi / 3, A_2 = pi / 4.
  float w[9];
  w[0] = 3.14159265 * 0.282095;
  w[1] = 2.09439510 * 0.488603 * n.y;
  w[2] = 2.09439510 * 0.488603 * n.z;
  w[3] = 2.09439510 * 0.488603 * n.x;
  w[4] = 0.78539816 * 1.092548 * n.x * n.y;
  w[5] = 0.78539816 * 1.092548 * n.y * n.z;
  w[6] = 0.78539816 * 0.315392 * (3.0 * n.z * n.z - 1.0);
  w[7] = 0.78539816 * 1.092548 * n.x * n.z;
  w[8] = 0.78539816 * 0.546274 * (n.x * n.x - n.y * n.y);
  vec3 irradiance = vec3(0.0);
  for (int k = 0; k < 9; ++k)
  {
    vec2 st = vec2(s, (float(k) * mlProbeGrid.y + probe.y) / rows);
    irradiance += w[k] * textureLod(mlIrradianceProbes, st, 0.0).rgb;
  }
  return max(irradiance, vec3(0.0));
}
