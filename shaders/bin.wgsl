// Tiled culling of ranged lights: for each 16×16-pixel tile, the list of the lights whose
// range can reach it, in light order (so that a tile's sums are bit-identical to the unculled
// ones: every light left out contributes exactly 0 there). Three passes: count per tile,
// prefix-sum over tiles, write per tile. The per-tile passes may be dispatched a band of tile
// rows at a time (from `params.bin_row`), so that the lab spreads them over frames. Composed
// after scene.wgsl; its Rust side is src/gpu/bin.rs.

// Counts, then (after bin_scan) each tile's first entry; [tiles] holds the total.
@group(0) @binding(5) var<storage, read_write> tile_offsets: array<u32>;
// The lists, one after another.
@group(0) @binding(6) var<storage, read_write> tile_lights: array<u32>;

const WORKGROUP: u32 = 256u;

// The tile's footprint on the plane: the quadrilateral under its corner rays; unbounded when
// a corner ray misses the plane (the horizon crosses the tile), and then every light is in.
struct Footprint {
    corners: array<vec2<f32>, 4>,
    bounded: bool,
    // The largest coordinate, for the rounding margin.
    extent: f32,
}

fn tile_footprint(tile: vec2<u32>) -> Footprint {
    var f: Footprint;
    f.bounded = true;
    f.extent = 0.0;
    let x0 = f32(tile.x * TILE_SIDE);
    let y0 = f32(tile.y * TILE_SIDE);
    let x1 = f32(min((tile.x + 1u) * TILE_SIDE, params.width));
    let y1 = f32(min((tile.y + 1u) * TILE_SIDE, params.height));
    let pixels = array<vec2<f32>, 4>(
        vec2<f32>(x0, y0),
        vec2<f32>(x1, y0),
        vec2<f32>(x1, y1),
        vec2<f32>(x0, y1),
    );
    for (var k = 0u; k < 4u; k++) {
        let hit = plane_hit(camera_ray(pixels[k]));
        if hit.w == 0.0 {
            f.bounded = false;
        }
        f.corners[k] = hit.xy;
        f.extent = max(f.extent, max(abs(hit.x), abs(hit.y)));
    }
    return f;
}

fn cross2(a: vec2<f32>, b: vec2<f32>) -> f32 {
    return a.x * b.y - a.y * b.x;
}

// Whether the light's range can reach the footprint: its range sphere cut by the plane is a
// disc (centre under the light, radius sqrt(R² − z²)); it misses the tile if the disc and the
// quadrilateral are apart. The margin (0.1% of R plus 1e-5 of the coordinates' magnitude) is
// far above the f32 rounding of the hit points and of d² (~1e-6 relative), so a light left
// out contributes exactly 0 to every pixel of the tile: w(d) = 0 for d ≥ R.
fn light_in_tile(light: GpuLight, f: Footprint) -> bool {
    let range = light.position_range.w;
    if range <= 0.0 || !f.bounded {
        return true;
    }
    let c = light.position_range.xy;
    let z = light.position_range.z;
    let extent = max(f.extent, max(abs(c.x), abs(c.y))) + range;
    let margin = 1e-3 * range + 1e-5 * extent;
    let r2 = range * range - z * z;
    if r2 <= 0.0 && abs(z) > range + margin {
        return false;
    }
    let r = sqrt(max(r2, 0.0)) + margin;
    // Apart from the quadrilateral's bounding box by more than r: apart from it.
    let lo = min(min(f.corners[0], f.corners[1]), min(f.corners[2], f.corners[3]));
    let hi = max(max(f.corners[0], f.corners[1]), max(f.corners[2], f.corners[3]));
    if any(c < lo - r) || any(c > hi + r) {
        return false;
    }
    // The orientation of the corners (the sign of the quadrilateral's area).
    var area = 0.0;
    for (var k = 0u; k < 4u; k++) {
        area += cross2(f.corners[k], f.corners[(k + 1u) % 4u]);
    }
    var inside = true;
    for (var k = 0u; k < 4u; k++) {
        let a = f.corners[k];
        let edge = f.corners[(k + 1u) % 4u] - a;
        if cross2(edge, c - a) * area < 0.0 {
            inside = false;
        }
        // The distance from the disc's centre to this edge.
        let t = clamp(dot(c - a, edge) / max(dot(edge, edge), 1e-30), 0.0, 1.0);
        if length(c - (a + t * edge)) <= r {
            return true;
        }
    }
    return inside;
}

var<workgroup> wg_count: atomic<u32>;

// The tile of a workgroup of a band dispatched from tile row `params.bin_row`.
fn band_tile(wid: vec3<u32>) -> vec2<u32> {
    return vec2<u32>(wid.x, wid.y + params.bin_row);
}

// One workgroup per tile: how many lights reach it.
@compute @workgroup_size(256)
fn bin_count(@builtin(workgroup_id) band: vec3<u32>, @builtin(local_invocation_index) li: u32) {
    let tile = band_tile(band);
    if li == 0u {
        atomicStore(&wg_count, 0u);
    }
    workgroupBarrier();
    let f = tile_footprint(tile);
    for (var k = li; k < params.light_count; k += WORKGROUP) {
        if light_in_tile(lights[k], f) {
            atomicAdd(&wg_count, 1u);
        }
    }
    workgroupBarrier();
    if li == 0u {
        tile_offsets[tile.y * params.tiles_x + tile.x] = atomicLoad(&wg_count);
    }
}

// a + b, saturating at the largest u32 (a tile list total beyond it is beyond any capacity).
fn saturating_add(a: u32, b: u32) -> u32 {
    return select(a + b, 0xffffffffu, a > 0xffffffffu - b);
}

var<workgroup> wg_sums: array<u32, WORKGROUP>;

// Inclusive prefix sums of wg_sums, in place (Hillis & Steele); all threads call it.
fn workgroup_scan(li: u32) {
    for (var d = 1u; d < WORKGROUP; d *= 2u) {
        var add = 0u;
        if li >= d {
            add = wg_sums[li - d];
        }
        workgroupBarrier();
        wg_sums[li] = saturating_add(wg_sums[li], add);
        workgroupBarrier();
    }
}

// One workgroup: the counts become each tile's first entry, the total goes after them.
@compute @workgroup_size(256)
fn bin_scan(@builtin(local_invocation_index) li: u32) {
    let n = params.tiles_x * params.tiles_y;
    let per = (n + WORKGROUP - 1u) / WORKGROUP;
    let begin = min(li * per, n);
    let end = min(begin + per, n);
    var sum = 0u;
    for (var k = begin; k < end; k++) {
        sum = saturating_add(sum, tile_offsets[k]);
    }
    wg_sums[li] = sum;
    workgroupBarrier();
    workgroup_scan(li);
    var running = wg_sums[li] - sum;
    for (var k = begin; k < end; k++) {
        let count = tile_offsets[k];
        tile_offsets[k] = running;
        running = saturating_add(running, count);
    }
    if li == WORKGROUP - 1u {
        tile_offsets[n] = wg_sums[li];
    }
}

// One workgroup per tile: its list, in light order. Each thread takes a contiguous run of
// lights, counts its own, and one prefix sum over the threads places every run (one scan per
// tile rather than one per 256 lights: barriers cost more than tests on a CPU driver).
@compute @workgroup_size(256)
fn bin_write(@builtin(workgroup_id) band: vec3<u32>, @builtin(local_invocation_index) li: u32) {
    let tile = band_tile(band);
    let f = tile_footprint(tile);
    let per = (params.light_count + WORKGROUP - 1u) / WORKGROUP;
    let begin = min(li * per, params.light_count);
    let end = min(begin + per, params.light_count);
    var mine = 0u;
    for (var k = begin; k < end; k++) {
        if light_in_tile(lights[k], f) {
            mine += 1u;
        }
    }
    wg_sums[li] = mine;
    workgroupBarrier();
    workgroup_scan(li);
    var at = tile_offsets[tile.y * params.tiles_x + tile.x] + wg_sums[li] - mine;
    for (var k = begin; k < end; k++) {
        if light_in_tile(lights[k], f) {
            if at < params.tile_capacity {
                tile_lights[at] = k;
            }
            at += 1u;
        }
    }
}
