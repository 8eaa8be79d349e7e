// Reading the rain cells' table (rain_cells.frag): the drops that can reach a texel of the field.
uniform highp isampler2D u_impact_table;
uniform vec2 u_impact_grid;  // cells per side, texels per cell (u_rain.xy of rain_impacts.glsl)

// The first of the 2x2 cells whose drops can reach texel position p (a drop reaches half a cell); the
// others are +(1, 0), +(0, 1), +(1, 1).
ivec2 rain_cells_near(vec2 p) { return ivec2(floor(p / u_impact_grid.y - 0.5)); }

// Entry `part` (0: ring, 1: splash) of `cell`'s drop k slots back, and where it hit in texels. A cell one
// beyond either edge of the grid is its periodic copy; no integer % (llvmpipe has no vector division).
vec4 rain_cell(ivec2 cell, int k, int part, out vec2 spot) {
    int n = int(u_impact_grid.x);
    ivec2 wrapped = cell + n * (ivec2(lessThan(cell, ivec2(0))) - ivec2(greaterThanEqual(cell, ivec2(n))));
    vec4 v = intBitsToFloat(texelFetch(u_impact_table, 2 * wrapped + ivec2(k, part), 0));
    spot = (vec2(cell) + v.xy) * u_impact_grid.y;
    return v;
}
