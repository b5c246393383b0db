// Positions are earth-centred (ECEF, metres) in double-single form: inPosition + inTexCoord2. The
// eye's position is subtracted in that form first, so the eye-relative position keeps float's
// relative precision at every distance (3 cm at 300 km, micrometres at a metre) while the buffers
// do not depend on the eye and are reused from one viewpoint to the next.
precise out vec3 vPosition;
in vec3 inPosition;      // ECEF, high part (float of the double)
in vec3 inTexCoord2;     // ECEF, low part (double − high)
in vec4 inTexCoord3;     // xyz: ellipsoid normal (ECEF); w: height above the ellipsoid as placed, metres
in vec3 inNormal;        // surface normal (ECEF), for shading (signed normalized bytes)
in vec4 inTexCoord;      // (shorts) x: terrain elevation, metres; y: flags (debug: 1 filled void, 2 missing tile, 4 tile seam;
                         // 8, 16, 24: naming rule, see Terrain.frag); zw: grid row and column in the patch
uniform mat4 g_ViewProjectionMatrix;
uniform vec3 m_EyeHigh;
uniform vec3 m_EyeLow;
uniform vec3 m_EyeFoot;          // the ellipsoid point under the eye, relative to the eye (ECEF axes)
uniform mat3 m_EcefToEye;        // rotation to the eye's frame in jME axes (x east, y up, z south)
uniform float m_LiftPerSquareMetre; // refraction: lift = k·d²/2R
uniform float m_MeanRadius;
out vec3 vNormal;
out float vElevation;
flat out int vFlags;      // not interpolated: a triangle takes its provoking vertex's flags
flat out int vVertex;     // the provoking vertex's number in its geometry (see Terrain.frag)
out vec2 vGrid;           // the grid position, interpolated ...
flat out vec2 vGridLast;  // ... and the provoking vertex's: which side of it tells its two triangles apart

void main() {
    precise vec3 rel = (inPosition - m_EyeHigh) + (inTexCoord2 - m_EyeLow);
    // Ground distance between the feet (the chord's arc on the mean sphere), as Refraction computes it.
    vec3 chord = rel - inTexCoord3.w * inTexCoord3.xyz - m_EyeFoot;
    float ground = 2.0 * m_MeanRadius * asin(min(1.0, length(chord) / (2.0 * m_MeanRadius)));
    precise vec3 lifted = rel + (m_LiftPerSquareMetre * ground * ground) * inTexCoord3.xyz;
    vPosition = m_EcefToEye * lifted;
    vNormal = m_EcefToEye * inNormal;
    vElevation = inTexCoord.x;
    vFlags = int(inTexCoord.y + 0.5);
    vVertex = gl_VertexID;
    vGrid = inTexCoord.zw;
    vGridLast = inTexCoord.zw;
    gl_Position = g_ViewProjectionMatrix * vec4(vPosition, 1.0);
}
