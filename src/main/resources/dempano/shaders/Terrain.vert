// Positions are already eye-relative (world = local east-up-south, eye at the origin).
in vec3 inPosition;
in vec3 inNormal;
in vec2 inTexCoord;      // x: terrain elevation, metres
uniform mat4 g_WorldViewProjectionMatrix;
out vec3 vPosition;
out vec3 vNormal;
out float vElevation;

void main() {
    vPosition = inPosition;
    vNormal = inNormal;
    vElevation = inTexCoord.x;
    gl_Position = g_WorldViewProjectionMatrix * vec4(inPosition, 1.0);
}
