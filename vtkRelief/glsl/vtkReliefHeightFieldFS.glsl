// Mesolight relief: height-field access shared by every march method.
//
// Relief texture (seed 000, §4.1): tangent-space normal packed as (n+1)/2 in RGB, depth in A with
// 0 = the mesh surface and 1 = the deepest point. Texture space is (u, v, depth).

uniform sampler2D mlReliefTexture;
uniform float mlDepthScale;    // world depth of depth = 1 over the world length of one u unit
uniform float mlGradientScale; // 1 / depth scale the normals were baked with (0: flat bake)
uniform float mlTexelAspect;   // texture height / width in texels (texels are square)
uniform int mlLinearSteps;
uniform int mlRefinementSteps;

// Marches take explicit level 0: implicit derivatives are undefined inside divergent loops.
float mlDepthAt(vec2 uv)
{
  return textureLod(mlReliefTexture, uv, 0.0).a;
}

// (d depth / du, d depth / dv) recovered from the baked normal n ~ (k dd/dx, k dd/dy, 1), where x = u
// and y = v * aspect are measured in texture widths (vtkReliefTextureFilter's convention).
vec2 mlDepthGradient(vec2 uv)
{
  vec3 n = textureLod(mlReliefTexture, uv, 0.0).rgb * 2.0 - 1.0;
  float nz = max(n.z, 1e-4);
  return vec2(n.x, n.y * mlTexelAspect) * (mlGradientScale / nz);
}
