// The 8-point Gauss-Legendre rule on [-1, 1] (nodes AL_GL_X, weights AL_GL_W) for
// families that integrate with a fixed rule rather than the key nodes (the peak
// methods' low-N edges, method/peak_lobe_edge.glsl). Values to 17 digits (round-trip a
// double), from the Legendre polynomial's roots; exact for polynomials of degree 15.
#define AL_NODES 8
const real AL_GL_X[8] = AL_ARRAY_BEGIN(real, 8)
    AL_R(-9.60289856497536176e-01), AL_R(-7.96666477413626728e-01),
    AL_R(-5.25532409916328991e-01), AL_R(-1.83434642495649780e-01),
    AL_R(1.83434642495649780e-01), AL_R(5.25532409916328991e-01),
    AL_R(7.96666477413626728e-01), AL_R(9.60289856497536176e-01) AL_ARRAY_END;
const real AL_GL_W[8] = AL_ARRAY_BEGIN(real, 8)
    AL_R(1.01228536290376689e-01), AL_R(2.22381034453374343e-01),
    AL_R(3.13706645877887047e-01), AL_R(3.62683783378361768e-01),
    AL_R(3.62683783378361768e-01), AL_R(3.13706645877887047e-01),
    AL_R(2.22381034453374343e-01), AL_R(1.01228536290376689e-01) AL_ARRAY_END;
