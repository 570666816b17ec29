// SPDX-License-Identifier: BSD-3-Clause
// Mesolight relief: irradiance from a grid of SH9 radiance probes over the relief's texture
// (e.g. a virtual light field's light at the surface), evaluated at the relief's perturbed
// normal: E(n) = sum_lm A_l L_lm Y_lm(n) with Ramamoorthi and Hanrahan's constants ("An
// efficient representation for irradiance environment maps", eq. 8 and 12), the real SH basis
// of filters/Lighting (EnvironmentMaps.h) in world coordinates.
//
// The texture (vtkIrradianceProbesTexture) is Nu x 7 Nv RGBA, seven blocks of Nv rows: blocks 0-1
// hold red's L_0..L_7, 2-3 green's, 4-5 blue's, block 6 the three L_8. A linear fetch inside a
// block interpolates its coefficients bilinearly between the four nearest probes; the fetch is
// clamped to the block's texel centres, which clamps at the grid's border (probe (i, j) stands
// at ((i + 1/2) / Nu, (j + 1/2) / Nv)).

uniform sampler2D mlIrradianceProbes;
uniform vec2 mlProbeGrid; // (Nu, Nv)

// Irradiance at texture coordinates uv for the unit world normal n, clamped at 0 (to be
// multiplied by albedo / pi).
vec3 mlProbeIrradiance(vec2 uv, vec3 n)
{
  vec2 probe = clamp(uv * mlProbeGrid, vec2(0.5), mlProbeGrid - vec2(0.5));
  float s = probe.x / mlProbeGrid.x;
  float t = probe.y / (7.0 * mlProbeGrid.y);
  float block = 1.0 / 7.0;
  // A_l Y_lm(n) in the order of SH9 (Y00, Y1-1, Y10, Y11 | Y2-2, Y2-1, Y20, Y21 | Y22), with
  // A_0 = pi, A_1 = 2 pi / 3, A_2 = pi / 4.
  vec4 w0 = vec4(3.14159265 * 0.282095, 2.09439510 * 0.488603 * vec3(n.y, n.z, n.x));
  vec4 w1 = 0.78539816 *
    vec4(1.092548 * n.x * n.y, 1.092548 * n.y * n.z, 0.315392 * (3.0 * n.z * n.z - 1.0),
      1.092548 * n.x * n.z);
  float w8 = 0.78539816 * 0.546274 * (n.x * n.x - n.y * n.y);
  vec3 irradiance =
    vec3(dot(textureLod(mlIrradianceProbes, vec2(s, t), 0.0), w0) +
        dot(textureLod(mlIrradianceProbes, vec2(s, t + block), 0.0), w1),
      dot(textureLod(mlIrradianceProbes, vec2(s, t + 2.0 * block), 0.0), w0) +
        dot(textureLod(mlIrradianceProbes, vec2(s, t + 3.0 * block), 0.0), w1),
      dot(textureLod(mlIrradianceProbes, vec2(s, t + 4.0 * block), 0.0), w0) +
        dot(textureLod(mlIrradianceProbes, vec2(s, t + 5.0 * block), 0.0), w1)) +
    textureLod(mlIrradianceProbes, vec2(s, t + 6.0 * block), 0.0).rgb * w8;
  return max(irradiance, vec3(0.0));
}
