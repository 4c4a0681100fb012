// What a pixel that sees no surface shows (SPEC.md section 5): the sky above the horizon, the
// ground below, white (radiance = luminance / 683), as core/daylight/sky_model.cpp computes them, and the
// sun's disc where the pixel's ray falls inside it. Needs brdf.glsl (PI) before it.
uniform int skyModel;                 // 0 no sky, 1 uniform, 2 cie_overcast, 3 cie_general, 4 perez
uniform float skyZenithRadiance;      // Lz / 683, W sr^-1 m^-2
uniform float groundRadiance;         // the ground's luminance / 683
uniform vec3 skyTowardSun;            // what cie_general and perez are relative to
uniform vec4 cieAbcd;                 // ISO 15469's a, b, c, d (perez: its a, b, c, d)
uniform float cieE;
uniform float cieNormalisation;       // 1 / (f(Zs) phi(0)); perez: 1 / lv(zenith)
uniform vec3 sunToward;               // the disc's centre
uniform float sunCosHalfAngle;
uniform vec3 sunDiscRadiance;         // 0: no disc (none, a delta sun, or one below the horizon)

vec3 backgroundRadiance(vec3 w) {
    float l = 0.0;
    if (skyModel != 0) {
        if (w.y > 0.0) {
            float r = 1.0;
            if (skyModel == 2) r = (1.0 + 2.0 * w.y) / 3.0;
            if (skyModel == 3) {
                const float c = clamp(dot(w, skyTowardSun), -1.0, 1.0), chi = acos(c);
                const float f = 1.0 + cieAbcd.z * (exp(cieAbcd.w * chi) - exp(cieAbcd.w * PI * 0.5)) + cieE * c * c;
                r = f * (1.0 + cieAbcd.x * exp(cieAbcd.y / w.y)) * cieNormalisation;
            }
            if (skyModel == 4) {  // SPEC.md section 6: zeta at most 84 degrees, lv at least 0
                const float c = clamp(dot(w, skyTowardSun), -1.0, 1.0), gamma = acos(c);
                const float gradation = 1.0 + cieAbcd.x * exp(cieAbcd.y / max(w.y, 0.104528));
                r = max(gradation * (1.0 + cieAbcd.z * exp(cieAbcd.w * gamma) + cieE * c * c), 0.0) * cieNormalisation;
            }
            l = skyZenithRadiance * r;
        } else {
            l = groundRadiance;
        }
    }
    return vec3(l) + (dot(w, sunToward) >= sunCosHalfAngle ? sunDiscRadiance : vec3(0.0));
}
