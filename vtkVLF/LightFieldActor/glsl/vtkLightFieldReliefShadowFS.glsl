// SPDX-License-Identifier: BSD-3-Clause
// The movable object's shadow on a relief lit by the field (vtkLightFieldReliefShadowHook): the
// relief mappers' radiance hook (vtkReliefRadianceHook), called with the relief's linear radiance
// at its hit point
// before the exposure, shades it by the walkthrough's own shadow code (vtkLightFieldShadowFS.glsl,
// spliced in before this with ML_SHADOW_RECEIVER_GIVEN): the same maps, mode and share of the
// lighting as the flat walls, at the displaced point the relief shows and the wall's macro normal
// (the normal the flat wall is shaded with, so relief and wall darken alike).
#define ML_RADIANCE_HOOK
uniform mat4 mlViewToUnitSphere; // view coordinates -> the field's unit sphere

vec3 mlRadianceHook(vec3 radiance, vec3 pointVC, vec3 normalVC, vec3 kd)
{
  vec3 p = (mlViewToUnitSphere * vec4(pointVC, 1.0)).xyz;
  vec3 n = normalize(mat3(mlViewToUnitSphere) * normalVC);
  return mlShadowedAt(radiance, p, n, kd);
}
