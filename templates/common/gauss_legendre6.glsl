// The 6-point Gauss-Legendre rule on [-1, 1] (nodes AL_GL_X, weights AL_GL_W) for
// families that integrate with a fixed rule rather than the key nodes (the Phong peak
// methods' low-N edges, method/peak_lobe_edge.glsl). Values to 17 digits (round-trip a
// double), the Legendre polynomial's roots by Newton's method in double; exact for
// polynomials of degree 11.
#define AL_NODES 6
const real AL_GL_X[6] = AL_ARRAY_BEGIN(real, 6)
    AL_R(-9.32469514203152050e-01), AL_R(-6.61209386466264593e-01), AL_R(-2.38619186083196932e-01), AL_R(2.38619186083196932e-01), AL_R(6.61209386466264593e-01), AL_R(9.32469514203152050e-01) AL_ARRAY_END;
const real AL_GL_W[6] = AL_ARRAY_BEGIN(real, 6)
    AL_R(1.71324492379170495e-01), AL_R(3.60761573048138606e-01), AL_R(4.67913934572691037e-01), AL_R(4.67913934572691037e-01), AL_R(3.60761573048138606e-01), AL_R(1.71324492379170495e-01) AL_ARRAY_END;
