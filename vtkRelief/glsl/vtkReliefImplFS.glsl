// SPDX-License-Identifier: BSD-3-Clause
  // ---- Mesolight relief (vtkReliefMapper): march the height field below this fragment ----
  // Tangent frame scaled to texture units: dP/du and dP/dv from screen-space derivatives
  // (taken in uniform control flow above), the smooth tangent direction from the vertices.
  vec3 mlN = normalVCVSOutput;
  float mlDet = mlDUVdx.x * mlDUVdy.y - mlDUVdy.x * mlDUVdx.y;
#ifndef ML_FAR_RAYS
#define ML_MISS discard
#endif
  vec2 mlUV = mlTCoordVC;
  vec3 mlPos = vertexVC.xyz;
  vec3 mlHit = vec3(mlUV, 0.0);
  vec3 mlHitPos = mlPos;
  vec3 mlShadingNormal = mlN;
  // Each kept view ray's linear radiance but the light set's, and what the light set and the
  // colour's last steps need of it: the light set's lights are summed for all rays at once, after
  // they are traced (mlLightSetIrradiance).
  vec3 mlRayRadiance[ML_RAY_SLOTS];
  mlLitRay mlRayLit[ML_RAY_SLOTS];
  vec3 mlRayHitPos[ML_RAY_SLOTS];
  vec2 mlRayHitUV[ML_RAY_SLOTS];
  // The base level's normal at the hit, kept for the light set where the shading normal is the
  // footprint's (mlLitRay).
  vec3 mlFacetNormal = mlN;
  int mlRaysKept = 0;
  // The hit's texture frame (the same for every view ray of the pixel: the mesh's).
  mat3 mlWorldToTexture = mat3(0.0);
  // How far a far view ray enters beside the pixel's major axis (texture coordinates): its
  // footprint's normals are filtered that far back, on the axis (ML_FAR_RAYS).
  vec2 mlAcrossShiftUV = vec2(0.0);
  bool mlHasFrame = abs(mlDet) > 1e-30;
#ifdef ML_FAR_RAYS
  // Several view rays per far pixel (level of detail): at a grazing view a far pixel's
  // footprint is long along one axis, and one view ray, however exact, meets one of the facets
  // it covers where the supersampled frame averages them all (which facets the view reaches
  // and their shadows, which no filtering at one hit gives). Where the footprint's major axis
  // exceeds two texels, about one ray per minor axis' length along it (rounded up to an odd
  // count, at most ML_FAR_RAYS, an odd number: 3 at 45 and 80 degrees by default) enters the
  // pixel at the points of an N-rooks pattern (Shirley 1991, "Discrepancy as a quality measure
  // for sample distributions"): evenly spaced along its major screen axis and each in a strip of
  // its own across it (the rank-1 lattice of generator (1, 2), the centre ray at the centre; 3
  // rays lie on a diagonal). Each is traced and shaded as the pixel's one ray would be (its
  // footprint's level of detail: measured better than the share's finer level,
  // docs/relief-methods.md) and the colours are averaged. Spread across as well, the hits (which
  // facets the rays meet, and the shadows marched from them) sample the whole footprint; the
  // normals stay filtered over each ray's strip of the pixel, whose filter already spans the
  // pixel's width across, so they are read on the major axis (mlAcrossShiftUV): read at the
  // hit, the filter would reach past the pixel. Against the rays on the major axis alone, far
  // error 5.94 -> 5.43 levels under the courtyard, 3.78 -> 3.56 under the sunset and 8.20 ->
  // 8.06 under the VTK lights (docs/relief-methods.md). Elsewhere one ray: near pixels draw the
  // frame of level of detail off.
  vec2 mlAxisX = mlDUVdx * mlTextureSize;
  vec2 mlAxisY = mlDUVdy * mlTextureSize;
  bool mlSplitX = dot(mlAxisX, mlAxisX) >= dot(mlAxisY, mlAxisY);
  float mlMajorTexels = length(mlSplitX ? mlAxisX : mlAxisY);
  float mlMinorTexels = abs(mlAxisX.x * mlAxisY.y - mlAxisX.y * mlAxisY.x) / max(mlMajorTexels, 1e-30);
  // An odd count, so that one ray passes through the pixel's centre: its hit is the depth
  // written, and whether it misses the relief (a silhouette) decides the pixel's coverage as
  // the one ray did; an off-centre ray that misses is left out of the average.
  int mlRays = mlMajorTexels > 2.0
    ? clamp(int(ceil(mlMajorTexels / max(mlMinorTexels, 1e-6) - 1e-3)) | 1, 1, ML_FAR_RAYS)
    : 1;
  mlPixelViewRays = mlRays;
  vec3 mlCentreHit = mlHit, mlCentreHitPos = mlHitPos, mlCentreShadingNormal = mlShadingNormal;
#define ML_MISS if (2 * mlRay + 1 == mlRays) { discard; } continue
  for (int mlRay = 0; mlRay < mlRays; ++mlRay)
  {
    // The ray's offsets from the pixel's centre, in pixels: along the major screen axis and
    // across it (the lattice's strip: (ray - centre) * 2 + centre, modulo the count).
    int mlCentreRay = mlRays / 2;
    int mlAcrossStrip = ((mlRay - mlCentreRay) * 2 + mlCentreRay + 2 * mlRays) % mlRays;
    float mlAlongOffset = (float(mlRay) + 0.5) / float(mlRays) - 0.5;
    float mlAcrossOffset = (float(mlAcrossStrip) + 0.5) / float(mlRays) - 0.5;
    vec2 mlOffsetXY = mlSplitX ? vec2(mlAlongOffset, mlAcrossOffset)
                               : vec2(mlAcrossOffset, mlAlongOffset);
    mlUV = mlTCoordVC + mlOffsetXY.x * mlDUVdx + mlOffsetXY.y * mlDUVdy;
    mlPos = vertexVC.xyz + mlOffsetXY.x * mlDPdx + mlOffsetXY.y * mlDPdy;
    mlAcrossShiftUV = mlAcrossOffset * (mlSplitX ? mlDUVdy : mlDUVdx);
    // What each ray's shading sets, back to their values before the first.
    mlNormalLength = 1.0;
    mlSpecularPowerScale = 1.0;
    mlNormalSpreadVC = mat3(0.0);
    mlMarchLod = 0.0;
#ifdef ML_CURVED
    mlLeftLayer = false;
#endif
#ifdef ML_IRRADIANCE_PROBES
    mlShareWall = vec2(0.0);
#endif
    mlHit = vec3(mlUV, 0.0);
    mlHitPos = mlPos;
    mlShadingNormal = mlN;
    mlFacetNormal = mlN;
#endif
  vec2 mlWall = vec2(0.0); // a side wall's normal in (u, v) where the view ray met one
#ifdef ML_CURVED
  vec3 mlHitPlane = mlHit; // the hit in the entry point's plane coordinates (shadows start there)
#endif
  mlWorldToTexture = mat3(0.0);
#ifdef ML_LEVEL_OF_DETAIL
  mlViewRefinementSteps = mlRefinementBudget(); // the budget wherever the view march is skipped
#endif
  if (mlHasFrame)
  {
    vec3 dPdu = (mlDPdx * mlDUVdy.y - mlDPdy * mlDUVdx.y) / mlDet;
    vec3 dPdv = (mlDPdy * mlDUVdx.x - mlDPdx * mlDUVdy.x) / mlDet;
    float su = length(dPdu - mlN * dot(mlN, dPdu));
    float sv = length(dPdv - mlN * dot(mlN, dPdv));
    vec3 T = mlTangentVC - mlN * dot(mlN, mlTangentVC);
    T = dot(T, T) > 1e-20 ? normalize(T) : normalize(dPdu - mlN * dot(mlN, dPdu) + 1e-30);
    float handedness = dot(cross(dPdu, dPdv), mlN) < 0.0 ? -1.0 : 1.0;
    vec3 B = cross(mlN, T) * handedness;
    dPdu = T * su;
    dPdv = B * sv;
    float worldDepth = mlDepthScale * su; // world depth of depth = 1
    vec3 depthAxis = -mlN * max(worldDepth, 1e-6 * su);
    mlWorldToTexture = inverse(mat3(dPdu, dPdv, depthAxis));
    vec3 dir = mlCameraParallel != 0 ? vec3(0.0, 0.0, -1.0) : normalize(mlPos);
    vec3 q = mlWorldToTexture * dir; // texture-space change per unit of world distance
    mlCosView = clamp(-dot(dir, mlN), 0.0, 1.0);
    mlViewSteps = mlLinearSteps;
#ifdef ML_ADAPTIVE_STEPS
    // More steps at grazing angles, where the ray crosses more texels (Tatarchuk 2006).
    mlViewSteps = int(mix(float(mlLinearSteps), float(mlMinimumSteps), mlCosView) + 0.5);
#endif
#if ML_METHOD != ML_TEXTURE_MAPPING && ML_METHOD != ML_BUMP
    if (worldDepth > 0.0 && q.z > 1e-6)
    {
      // From depth 0 to depth 1. At grazing angles the span grows without bound; it is kept
      // finite so no NaN or Inf reaches the samplers (silhouettes discard such fragments).
      vec3 span = vec3(clamp(q.xy / q.z, vec2(-1e4), vec2(1e4)), 1.0);
#ifdef ML_CURVED
      // Curved mesh (Oliveira & Policarpo 2005): the ray's depth below the curved layer is
      // r(t) = t - c t^2 / (1 - k t) (c > 0 convex; k the layer's stretch along the ray,
      // mlQuadricDepth). The march ends where the ray leaves the layer: at its bottom (r = 1,
      // the first root of (c + k) t^2 - (1 + k) t + 1) when there is one, else back through its
      // top (r = 0, t = 1 / (c + k)) - there a search without a hit is a silhouette fragment.
      // The span is scaled so that end is t = 1: every search below runs unchanged; with
      // c = k = 0 it ends at t = 1 as on a flat mesh.
      vec2 mlQuadricFacing = gl_FrontFacing ? mlQuadricVC : -mlQuadricVC;
      mlQuadric = mlQuadricFacing / mlDepthScale;
      mlLayerStretch =
        2.0 * mlDepthScale * mlQuadricFacing * vec2(1.0, (su * su) / max(sv * sv, 1e-30));
      mlQuadricOrigin = mlHit.xy;
      float mlC = dot(mlQuadric, span.xy * span.xy);
      float mlK = mlC != 0.0 ? dot(mlQuadric * mlLayerStretch, span.xy * span.xy) / mlC : 0.0;
      float mlDisc = (1.0 + mlK) * (1.0 + mlK) - 4.0 * (mlC + mlK);
      bool mlExitsTop = mlDisc < 0.0;
      span *= mlExitsTop ? 1.0 / (mlC + mlK) : 2.0 / (1.0 + mlK + sqrt(mlDisc));
#endif
#ifdef ML_LEVEL_OF_DETAIL
      mlLevelOfDetailSteps(span, mlViewSteps);
#endif
      float t = mlTraceView(mlHit, span);
      mlWall = mlSideWall(mlHit, span, t);
      mlHit = mlHit + t * span;
#ifdef ML_IRRADIANCE_PROBES
      if (mlWall != vec2(0.0))
      {
        // The side wall's own share at the hit's depth down the wall (mlReliefShare).
        float mlWallFoot =
          textureLod(mlReliefTexture, clamp(mlHit.xy, 0.0, 1.0), 0.0).ML_DEPTH_CHANNEL;
        mlShareWall = mlWall;
        mlShareWallDepth = mlWallFoot > 0.0 ? clamp(mlHit.z / mlWallFoot, 0.0, 1.0) : 0.0;
      }
#endif
      mlHitPos = mlPos + dir * (mlHit.z / q.z);
#ifdef ML_CURVED
      mlHitPlane = mlHit;
      mlHit.xy = mlLayerUV(mlHit); // the texture coordinate at the hit's depth in the layer
#endif
#if defined(ML_CURVED) && defined(ML_SILHOUETTES)
      if (mlExitsTop && mlLeftLayer)
      {
        ML_MISS; // the ray passed the curved relief without a hit
      }
#endif
    }
#if defined(ML_CURVED) && defined(ML_SILHOUETTES)
    else if (worldDepth > 0.0 && dot(gl_FrontFacing ? mlQuadricVC : -mlQuadricVC, q.xy * q.xy) > 0.0)
    {
      ML_MISS; // a ray that does not go below the tangent plane misses a convex layer
    }
#endif
#endif
#ifdef ML_SILHOUETTES
    if (any(lessThan(mlHit.xy, vec2(0.0))) || any(greaterThan(mlHit.xy, vec2(1.0))))
    {
      ML_MISS;
    }
#endif
#if ML_METHOD != ML_TEXTURE_MAPPING
#ifdef ML_NORMAL_MOMENTS
    // The base level's normal where it still shows (blended below over the first level), and
    // under a light set everywhere: its far shadows start from the facet (mlLitRay).
    vec2 g = vec2(0.0);
    bool mlReadBaseNormal = mlShadeLod < 1.0;
#ifdef ML_LIGHT_SET
    mlReadBaseNormal = true; // one more lookup per far view ray
#endif
    if (mlReadBaseNormal)
    {
#ifdef ML_SURFACE_NORMALS
      g = mlSurfaceGradient(mlHit.xy);
#else
      g = mlGradientFromNormal(mlPackedNormalAt(mlHit.xy));
#endif
    }
#else
    // Derived normals are unit: no spread to read for Toksvig.
    vec3 mlFilteredNormal = vec3(0.0, 0.0, 1.0);
    vec2 g = vec2(0.0);
#ifdef ML_SURFACE_NORMALS
    // Near, the normal of the surface marched, blended into the filtered one over the first
    // level; each read only where its share is not zero (near pixels, and every pixel without
    // level of detail, read no filtered normal).
    float mlFilteredShare = clamp(mlShadeLod, 0.0, 1.0);
    if (mlFilteredShare < 1.0)
    {
      g = mlSurfaceGradient(mlHit.xy);
    }
#else
    float mlFilteredShare = 1.0;
#endif
    if (mlFilteredShare > 0.0)
    {
      mlMarchLod = mlShadeLod; // the shading normal at the footprint's level (level of detail)
#if defined(ML_FLOAT_TEXTURES) || defined(ML_STORED_NORMALS)
      mlFilteredNormal = mlPackedNormalAt(mlHit.xy);
      vec2 filtered = mlGradientFromNormal(mlFilteredNormal);
#else
      vec2 filtered = mlDepthGradient(mlHit.xy);
#endif
      mlMarchLod = 0.0; // shadows march level 0 again
      g = mix(g, filtered, mlFilteredShare);
    }
#endif
#if defined(ML_LEVEL_OF_DETAIL) && !defined(ML_CONE_PACKED) && !defined(ML_NORMAL_MOMENTS)
    // Only where the footprint's level is above the base: the bilinear blend of neighbouring
    // unit normals is a little short too, but near, the frame stays that of the exact march.
    mlNormalLength = mix(1.0, clamp(length(mlFilteredNormal), 1e-3, 1.0), clamp(mlShadeLod, 0.0, 1.0));
    // Toksvig's factor: the exponent s becomes ft * s, ft = |n| / (|n| + s (1 - |n|)).
    mlSpecularPowerScale =
      mlNormalLength / (mlNormalLength + mlSpecularPower * (1.0 - mlNormalLength));
#endif
#ifdef ML_CURVED
    // The slope of the curved layer under the hit.
    g += 2.0 * mlQuadric * mlLayerScale(mlHitPlane.z) * (mlHitPlane.xy - mlQuadricOrigin);
#endif
    vec3 pu = dPdu - mlN * (worldDepth * g.x);
    vec3 pv = dPdv - mlN * (worldDepth * g.y);
    mlShadingNormal = normalize(cross(pu, pv) * handedness);
    mlFacetNormal = mlShadingNormal;
#ifdef ML_NORMAL_MOMENTS
    if (mlShadeLod > 0.0)
    {
      // Blended in over the first mip level, so that near frames are exactly those of level of
      // detail off.
      vec3 v = -dir;
      vec3 n = mlVisibleNormal(
        mlHit.xy - mlAcrossShiftUV, vec3(dot(v, T), dot(v, B), dot(v, mlN)), mlShadeLod);
      n = T * n.x + B * n.y + mlN * n.z;
      float len = length(n);
      float blend = clamp(mlShadeLod, 0.0, 1.0);
      mlShadingNormal = normalize(mix(mlShadingNormal, n / max(len, 1e-6), blend));
      mlNormalLength = mix(1.0, clamp(len, 1e-3, 1.0), blend);
      mat3 mlFrame = mat3(T, B, mlN);
      mlNormalSpreadVC = (blend * blend) * (mlFrame * mlNormalSpread * transpose(mlFrame));
      mlMacroNormalVC = mlN;
      // Toksvig's factor for the highlight of the spread: ft = |n| / (|n| + s (1 - |n|)).
      mlSpecularPowerScale =
        mlNormalLength / (mlNormalLength + mlSpecularPower * (1.0 - mlNormalLength));
    }
#endif
#endif
    if (mlWall != vec2(0.0))
    {
      mlShadingNormal = normalize(mlWall.x * T + mlWall.y * B); // the walled relief's side wall
      mlFacetNormal = mlShadingNormal;
    }
  }
  // Bump mapping shades the undisplaced point but shadows it from the height below it.
  vec3 mlShadowPoint = mlHit;
#ifdef ML_CURVED
  mlShadowPoint = mlHitPlane;
#endif
#if ML_METHOD == ML_BUMP
  mlShadowPoint.z = mlDepthAt(mlHit.xy);
#endif
#if defined(ML_LEVEL_OF_DETAIL) && ML_METHOD != ML_MAXIMUM_MIPMAP
  // Where refinement stopped at the footprint the hit may lie up to one bracket inside the
  // height field, and a shadow ray leaving from there is blocked by the surface it starts on:
  // the shadow march starts the bracket's depth higher (far pixels only).
  if (mlFootprint > 1.0)
  {
    mlShadowPoint.z = max(0.0, mlShadowPoint.z -
        1.0 / (float(max(mlViewSteps, 1)) * exp2(float(mlViewRefinementSteps))));
  }
#endif
  vec3 diffuse = vec3(0.0);
  vec3 specular = vec3(0.0);
  float mlFirstLightVisible = 0.0;
  mlAccumulateLights(mlHitPos, mlShadingNormal, mlShadowPoint, mlWorldToTexture,
    mlHasFrame, diffuse, specular, mlFirstLightVisible);
  // Filtered normals (level of detail): the footprint's mean of n.l, and the energy of the
  // widened specular lobe kept ((1 + ft s) / (1 + s), Toksvig 2005).
  specular *= (1.0 + mlSpecularPowerScale * mlSpecularPower) / (1.0 + mlSpecularPower);
#if ML_OUTPUT == 1 || ML_OUTPUT == 2
  // One hit texture coordinate (u or v) as 24-bit fixed point in RGB, opaque (measurement).
  float mlFixed = floor(clamp(ML_OUTPUT == 1 ? mlHit.x : mlHit.y, 0.0, 1.0) * 16777215.0 + 0.5);
  float mlR = floor(mlFixed / 65536.0);
  float mlG = floor((mlFixed - 65536.0 * mlR) / 256.0);
  gl_FragData[0] = vec4(mlR, mlG, mlFixed - 65536.0 * mlR - 256.0 * mlG, 255.0) / 255.0;
#elif ML_OUTPUT == 3
  // Whether the first light reaches the hit point (facing it and not self-shadowed).
  gl_FragData[0] = vec4(vec3(mlFirstLightVisible), 1.0);
#else
  vec3 mlRadiance = ambientColor + diffuse * diffuseColor + specular * mlSpecularColor;
#ifdef ML_IRRADIANCE_PROBES
  // The probes' SH9 irradiance over the footprint's normals (their mean and second moment, world
  // coordinates; one normal near), with the relief's occlusion and inter-reflection
  // (mlProbeIndirect), Lambertian: albedo / pi times irradiance.
  mat3 mlViewToWorld = transpose(mlWorldToView);
  vec3 mlMeanNormalVC = mlNormalLength * mlShadingNormal;
  mlRadiance += mlProbeIndirect(mlHit.xy, mlViewToWorld * mlMeanNormalVC,
    mlViewToWorld * (mlNormalSpreadVC + outerProduct(mlMeanNormalVC, mlMeanNormalVC)) *
      mlWorldToView,
    mlViewToWorld * mlN, diffuseColor, mlFlatLightIrradiance(mlHitPos, mlN, mlHit.xy)) *
    (diffuseColor / 3.14159265);
#endif
  mlRayRadiance[mlRaysKept] = mlRadiance;
  mlRayHitPos[mlRaysKept] = mlHitPos;
  mlRayHitUV[mlRaysKept] = mlHit.xy;
  mlRayLit[mlRaysKept] = mlLitRay(mlShadingNormal, mlNormalLength, mlNormalSpreadVC,
    mlFacetNormal, mlShadowPoint, vec2(0.0));
#ifdef ML_CURVED
  mlRayLit[mlRaysKept].QuadricOrigin = mlQuadricOrigin;
#endif
  ++mlRaysKept;
#endif
#ifdef ML_FAR_RAYS
    if (2 * mlRay + 1 == mlRays) // the centre's
    {
      mlCentreHit = mlHit;
      mlCentreHitPos = mlHitPos;
      mlCentreShadingNormal = mlShadingNormal;
    }
  }
  mlPos = vertexVC.xyz;
  mlHit = mlCentreHit;
  mlHitPos = mlCentreHitPos;
  mlShadingNormal = mlCentreShadingNormal;
#endif
#if ML_OUTPUT != 1 && ML_OUTPUT != 2 && ML_OUTPUT != 3
#ifdef ML_LIGHT_SET
  vec3 mlRayIrradiance[ML_RAY_SLOTS];
  mlLightSetIrradiance(mlRayLit, mlRaysKept, mlWorldToTexture, mlHasFrame, mlRayIrradiance);
#endif
  // The pixel's colour: its kept view rays' colours averaged (one but far away, ML_FAR_RAYS).
  vec4 mlColourSum = vec4(0.0);
#if ML_OUTPUT == 4
  bool mlBadColour = false;
#endif
  for (int mlKept = 0; mlKept < ML_RAY_SLOTS; ++mlKept)
  {
    if (mlKept >= mlRaysKept)
    {
      break;
    }
    vec4 mlColour = vec4(mlRayRadiance[mlKept], opacity);
#if defined(ML_LIGHT_SET) || defined(ML_IRRADIANCE_PROBES)
#ifdef ML_LIGHT_SET
    // Lambertian under the environment: albedo / pi times irradiance.
    mlColour.rgb +=
      mlRayIrradiance[mlKept] * (diffuseColor / 3.14159265);
#endif
#ifdef ML_RADIANCE_HOOK
    // A vtkReliefRadianceHook's change of the linear radiance at the hit (view coordinates, the
    // macro normal), e.g. a light field's movable object's shadow (vtkLightFieldReliefShadowHook).
    mlColour.rgb = mlRadianceHook(mlColour.rgb, mlRayHitPos[mlKept], mlN, diffuseColor);
#endif
    // An emitter's own light (a lamp under the relief), which no shadow takes away; the exposure
    // scales the environment's shading.
    mlColour.rgb += mlEmission;
    mlColour.rgb *= mlExposure;
#ifdef ML_TONE_MAPPING
    mlColour.rgb = mlColour.rgb / (1.0 + mlColour.rgb); // Reinhard
#endif
#ifdef ML_ENCODE_SRGB
    mlColour.rgb = mlEncodeSrgb(mlColour.rgb); // beside an sRGB-encoded light field
#endif
#endif
#if ML_OUTPUT == 4
    // Checked before the albedo texture's clamp, which may turn a NaN into a number (GLSL leaves
    // clamp of NaN undefined) and would hide it from the check below.
    mlBadColour = mlBadColour || any(isnan(mlColour)) || any(isinf(mlColour));
#endif
#ifdef ML_ALBEDO_SAMPLER
    mlColour = clamp(mlColour, 0.0, 1.0) *
      textureGrad(ML_ALBEDO_SAMPLER, mlRayHitUV[mlKept], mlDUVdx, mlDUVdy);
#endif
    mlColourSum += mlColour;
  }
  gl_FragData[0] = mlColourSum / float(max(mlRaysKept, 1));
#endif
#if ML_OUTPUT == 4
  // Red where anything on the way to the colour was NaN or Inf (stress tests), else green.
  bool mlBad = any(isnan(mlHit)) || any(isinf(mlHit)) || any(isnan(mlHitPos)) ||
    any(isinf(mlHitPos)) || any(isnan(mlShadingNormal)) || any(isnan(gl_FragData[0])) ||
    any(isinf(gl_FragData[0])) || mlBadColour;
  gl_FragData[0] = mlBad ? vec4(1.0, 0.0, 0.0, 1.0) : vec4(0.0, 1.0, 0.0, 1.0);
#elif ML_OUTPUT == 5
  // Relief-texture samples this fragment took, shading and shadows of every light included, as
  // a 16-bit count in R (high) and G (low).
  float mlCount = float(min(mlSampleCount, 65535));
  gl_FragData[0] = vec4(floor(mlCount / 256.0), mod(mlCount, 256.0), 0.0, 255.0) / 255.0;
#endif
#ifdef ML_WRITE_DEPTH
  vec3 mlDepthPos = mlHitPos;
#ifdef ML_DEPTH_LIMIT
  // No deeper than the limit plane (vtkReliefProperty::SetDepthLimitPlane): where the hit lies
  // behind it, the view ray's crossing of the plane, between this fragment and its hit.
  float mlAbove = max(dot(mlDepthLimitVC.xyz, mlPos) + mlDepthLimitVC.w, 0.0);
  float mlHitAbove = dot(mlDepthLimitVC.xyz, mlHitPos) + mlDepthLimitVC.w;
  if (mlHitAbove < 0.0)
  {
    mlDepthPos = mix(mlPos, mlHitPos, mlAbove / (mlAbove - mlHitAbove));
  }
#endif
  vec4 mlClip = mlViewToClip * vec4(mlDepthPos, 1.0);
  gl_FragDepth = clamp(0.5 * (mlClip.z / mlClip.w) + 0.5, 0.0, 1.0);
#endif
