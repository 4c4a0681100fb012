// SPEC.md section 1 materials, the same formulas as render/trace/bsdf.cpp: Lambert plus GGX with
// separable Smith shadowing and no Fresnel term. n is already turned toward wo (two-sided).
const float PI = 3.14159265358979;

float smithG1(float cosTheta, float a2) {
    const float c2 = cosTheta * cosTheta;
    const float tan2 = max(0.0, 1.0 - c2) / c2;
    return 2.0 / (1.0 + sqrt(1.0 + a2 * tan2));
}

vec3 evalBsdf(vec3 n, vec3 wo, vec3 wi, vec3 albedo, vec3 specular, float alpha) {
    const float cosO = dot(n, wo), cosI = dot(n, wi);
    if (cosO <= 0.0 || cosI <= 0.0) return vec3(0.0);
    vec3 f = albedo * (1.0 / PI);
    if (max(specular.r, max(specular.g, specular.b)) > 0.0) {
        const vec3 h = normalize(wi + wo);
        const float nh = dot(n, h);
        const float a2 = alpha * alpha;
        const float d = nh * nh * (a2 - 1.0) + 1.0;
        const float D = a2 / (PI * d * d);
        f += specular * (D * smithG1(cosI, a2) * smithG1(cosO, a2) / (4.0 * cosI * cosO));
    }
    return f;
}
