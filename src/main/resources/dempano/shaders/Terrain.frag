in vec3 vPosition;
in vec3 vNormal;
in float vElevation;
flat in int vFlags;
flat in int vVertex;
in vec2 vGrid;
flat in vec2 vGridLast;
uniform vec3 g_CameraPosition;
uniform float m_RangeMetres;
uniform float m_HazeMetres;
uniform vec3 m_SunDirection;
uniform int m_VertexBase;
layout(location = 0) out vec4 outColour;
layout(location = 1) out uvec2 outRange;

// Hypsometric tint: lowland green, forest, pasture, rock, snow.
vec3 tint(float h) {
    if (h < 0.5) return vec3(0.28, 0.42, 0.55);                       // sea and lakes at 0 m
    vec3 c0 = vec3(0.36, 0.52, 0.30), c1 = vec3(0.30, 0.42, 0.24);
    vec3 c2 = vec3(0.55, 0.55, 0.38), c3 = vec3(0.50, 0.46, 0.42), c4 = vec3(0.93, 0.94, 0.96);
    if (h < 800.0) return mix(c0, c1, h / 800.0);
    if (h < 1800.0) return mix(c1, c2, (h - 800.0) / 1000.0);
    if (h < 2600.0) return mix(c2, c3, (h - 1800.0) / 800.0);
    if (h < 3200.0) return mix(c3, c4, (h - 2600.0) / 600.0);
    return c4;
}

void main() {
    // The exact range cut (ground distance ≈ horizontal distance in the eye's frame).
    if (length(vPosition.xz) > m_RangeMetres) {
        discard;
    }
    // The camera is at the origin for panoramas; the fly-through moves it.
    float range = length(vPosition - g_CameraPosition);
    // The range's float bits, and what names the triangle seen: its provoking vertex's number in
    // the scene (the geometry's first vertex's number plus gl_VertexID) and a bit. TerrainBuilder
    // makes every vertex the provoking vertex of at most two triangles, which lie on opposite sides
    // of a line through it in the patch's grid (its naming rule, flags 8–24: the cell's diagonal, the
    // other diagonal, or across a skirt), so the pair and the side name one triangle
    // (TerrainBuilder.VERTEX_BASE, SeenTriangleResolver). Reading gl_PrimitiveID instead made
    // llvmpipe assemble every primitive apart and shade each vertex once per triangle: 1.65 s
    // against 0.88 s of drawing at srtm3-150km (measured).
    vec2 d = vGrid - vGridLast; // (rows, columns) from the provoking vertex
    int rule = vFlags & 24;
    float side = rule == 0 ? d.y - d.x : rule == 8 ? d.x + d.y : rule == 16 ? d.y : d.x;
    outRange = uvec2(floatBitsToUint(range), uint(2 * (m_VertexBase + vVertex) + (side > 0.0 ? 0 : 1)));
#ifdef DISTANCE_ONLY
    outColour = vec4(0.0);
#else
    vec3 n = normalize(vNormal);
    float light = 0.30 + 0.70 * max(dot(n, m_SunDirection), 0.0);
    vec3 colour = tint(vElevation) * light;
    // Aerial perspective: far terrain fades toward a blue-grey that stays darker than the sky.
    float haze = 1.0 - exp(-range / m_HazeMetres);
    colour = mix(colour, vec3(0.62, 0.68, 0.78), 0.85 * haze);
#ifdef DEBUG_AIDS
    // Fly-through debugging: filled voids magenta, missing tiles red, tile seams yellow.
    if ((vFlags & 1) != 0) colour = mix(colour, vec3(1.0, 0.0, 1.0), 0.8);
    if ((vFlags & 2) != 0) colour = mix(colour, vec3(1.0, 0.1, 0.1), 0.6);
    if ((vFlags & 4) != 0) colour = vec3(1.0, 0.9, 0.0);
#endif
    outColour = vec4(colour, 1.0);
#endif
}
