// The types of CONTRACT.md 5, defined once however many arealight libraries a
// shader includes.
#ifndef AREALIGHT_TYPES
#define AREALIGHT_TYPES 1
// A shading point as the renderer has it: p, n (toward the outside) and v (toward
// the eye) in one space of its choosing, n and v of any length; param the exponent
// N (phong, blinn) or alpha (beckmann, ggx); f0 Schlick's reflectance at normal
// incidence (1 gives F = 1; phong ignores it).
struct ArealightSurface {
    vec3 p;
    vec3 n;
    vec3 v;
    float param;
    float f0;
};
// CONTRACT.md 2's diffuse and specular for unit light radiance.
struct ArealightShading {
    float diffuse;
    float specular;
};
#endif
// Descriptor set of the tables a method samples (method=ltc). Their bindings: each
// sampler's own AREALIGHT_<LIGHT>_<DIST>_<NAME>_BINDING, else AREALIGHT_BINDING plus
// its index where the renderer defines AREALIGHT_BINDING, else the literal index
// (GLSL ES 3.10 takes only literal layout ids; the library does not define it).
#ifndef AREALIGHT_SET
#define AREALIGHT_SET 0
#endif
