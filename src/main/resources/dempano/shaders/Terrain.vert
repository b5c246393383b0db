// Positions are already eye-relative (world = local east-up-south, eye at the origin).
in vec3 inPosition;
in vec3 inNormal;
in vec2 inTexCoord;      // x: terrain elevation, metres; y: debug flags (1 filled void, 2 missing tile, 4 tile seam)
uniform mat4 g_WorldViewProjectionMatrix;
out vec3 vPosition;
out vec3 vNormal;
out float vElevation;
flat out int vFlags;      // not interpolated: a triangle takes its provoking vertex's flags

void main() {
    vPosition = inPosition;
    vNormal = inNormal;
    vElevation = inTexCoord.x;
    vFlags = int(inTexCoord.y + 0.5);
    gl_Position = g_WorldViewProjectionMatrix * vec4(inPosition, 1.0);
}
