// A light's boundary and its brightest point (src/light/boundary.rs; docs/design.md §1.14):
// where a glossy lobe peaks outside the light, the polar rule's pole is the boundary's point
// where the lobe is largest. Composed with polar.wgsl, whose lobe_value it reads.

// brightest's samples an arc and golden-section steps (src/light/boundary.rs).
const BRIGHTEST_SAMPLES: u32 = 16u;
const BRIGHTEST_STEPS: u32 = 24u;
// Where the brightest point is an arc's corner (src/light/boundary.rs CORNER_SNAP).
const CORNER_SNAP: f32 = 0.05;

// A smooth piece of a region's boundary (src/light/polar.rs Arc): a great circle's arc from a
// to b (circle.y = 0), or a cap's circle cos σ axis + sin σ (t1 cos ψ + t2 sin ψ),
// ψ = from + sweep s, with a = axis, b = t1, circle = (cos σ, sin σ, from, sweep).
struct Arc {
    a: vec3<f32>,
    b: vec3<f32>,
    t2: vec3<f32>,
    circle: vec4<f32>,
}

// Arc::at: the arc's direction at s ∈ [0, 1].
fn arc_at(arc: Arc, s: f32) -> vec3<f32> {
    if arc.circle.y == 0.0 {
        return normalize(arc.a + (arc.b - arc.a) * s);
    }
    let sc = sincos_precise(arc.circle.z + arc.circle.w * s);
    return arc.a * arc.circle.x + (arc.b * sc.y + arc.t2 * sc.x) * arc.circle.y;
}

// Arc::tangent: the unit tangent along the arc at its point x.
fn arc_tangent(arc: Arc, x: vec3<f32>) -> vec3<f32> {
    if arc.circle.y == 0.0 {
        return normalize(cross(cross(arc.a, arc.b), x));
    }
    return normalize(cross(arc.a, x));
}

// brightest: the point of the boundary arcs where the specular lobe is largest: the best of
// BRIGHTEST_SAMPLES + 1 samples an arc, narrowed by golden sections; (arc, s).
fn brightest(arcs: array<Arc, 5>, count: u32, v: vec3<f32>, alpha: vec2<f32>, f0: f32) -> vec2<f32> {
    let step = 1.0 / f32(BRIGHTEST_SAMPLES);
    var best = vec3<f32>(-1.0, 0.0, 0.0);
    for (var k = 0u; k < count; k++) {
        for (var i = 0u; i <= BRIGHTEST_SAMPLES; i++) {
            let s = f32(i) * step;
            let g = lobe_value(v, arc_at(arcs[k], s), alpha, f0, 0u);
            if g > best.x {
                best = vec3<f32>(g, f32(k), s);
            }
        }
    }
    let arc = arcs[u32(best.y)];
    var lo = max(best.z - step, 0.0);
    var hi = min(best.z + step, 1.0);
    // The golden ratio's conjugate, (√5 − 1)/2.
    let ratio = 0.6180339887498949;
    for (var i = 0u; i < BRIGHTEST_STEPS; i++) {
        // Both points' values from one call of the lobe (see polar.wgsl's polar_piece).
        var g = vec2<f32>(0.0);
        for (var q = 0u; q < 2u; q++) {
            let m = select(lo + ratio * (hi - lo), hi - ratio * (hi - lo), q == 0u);
            g[q] = lobe_value(v, arc_at(arc, m), alpha, f0, 0u);
        }
        if g.x >= g.y {
            hi = lo + ratio * (hi - lo);
        } else {
            lo = hi - ratio * (hi - lo);
        }
    }
    var s = 0.5 * (lo + hi);
    if s < CORNER_SNAP {
        s = 0.0;
    } else if s > 1.0 - CORNER_SNAP {
        s = 1.0;
    }
    return vec2<f32>(best.y, s);
}
