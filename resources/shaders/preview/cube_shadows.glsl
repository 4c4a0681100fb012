// Cube shadow maps spread over up to four cube map arrays (render/preview/shadow_maps.h,
// CubeShadowSet): cube i is cube i mod perArray of array i / perArray, each texel the distance
// from the cube's centre to the nearest surface. The index is the same for every fragment of a
// draw (one light or VPL of a loop whose bounds are uniforms), so indexing the sampler array by
// it is allowed (dynamically uniform).
float cubeShadowDistance(samplerCubeArray maps[4], int perArray, vec3 dir, int index) {
    const int a = index / perArray;
    return texture(maps[a], vec4(dir, float(index - a * perArray))).r;
}
