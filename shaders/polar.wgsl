// The renders' exact rule (src/light/polar.rs; docs/design.md §1.14): the integral over a
// convex region of directions in polar coordinates about a pole, stretched to the lobe
// (boundary.wgsl finds the pole off the light, fan.wgsl a polygon's diffuse lobe). The
// same functions by name and the same nodes as the f64 rule, in f32 with the precise
// trigonometry of sphere_light.wgsl, rect_light.wgsl and disk_light.wgsl (WGSL's own sin, cos
// and atan may be 2⁻¹¹ off, which would bend the substitutions the weights assume).

// Writes: an array written at an index computed at run time is written at a constant index
// in a loop over the array (`if k == at`). Mesa's GLSL compiler turns each such write into a
// conditional write of every element, again in every copy it inlines, which took a rect's
// rule 44 s to compile on llvmpipe's OpenGL (3.8 s written so; docs/design.md §1.14).

// Bounds::planes' length: a rect clipped by the horizon has five edges.
const MAX_PLANES: u32 = 5u;
// Polar::cuts' length: a clipped rect's five corners and five feet, and the four quarter turns.
const MAX_CUTS: u32 = 16u;
// Nodes a dimension and piece (src/light/polar.rs RULE_NODES, RULE_NODES_ANISO).
const RULE_NODES: u32 = 12u;
const RULE_NODES_ANISO: u32 = 24u;
const DIFFUSE_NODES: u32 = 8u;
// "No end": T = tan(u/2) at u = π.
const T_INFINITE: f32 = 1e30;

// The 8-, 12- and 24-point Gauss–Legendre rules on [−1, 1], as src/light/sphere/quadrature.rs
// gauss_legendre computes them (the positive half; the rules are symmetric).
// tests/shaders/constants.rs checks them against the Rust rule.
const GL8_NODES: array<f32, 4> = array<f32, 4>(
    0.18343464249564980, 0.52553240991632899, 0.79666647741362684, 0.96028985649753629,
);
const GL8_WEIGHTS: array<f32, 4> = array<f32, 4>(
    0.36268378337836199, 0.31370664587788738, 0.22238103445337445, 0.10122853629037679,
);
const GL12_NODES: array<f32, 6> = array<f32, 6>(
    0.12523340851146894, 0.36783149899818018, 0.58731795428661748,
    0.76990267419430469, 0.90411725637047480, 0.98156063424671924,
);
const GL12_WEIGHTS: array<f32, 6> = array<f32, 6>(
    0.24914704581340288, 0.23349253653835478, 0.20316742672306584,
    0.16007832854334633, 0.10693932599531818, 0.04717533638651183,
);
const GL24_NODES: array<f32, 12> = array<f32, 12>(
    0.06405689286260563, 0.19111886747361631, 0.31504267969616340, 0.43379350762604518,
    0.54542147138883956, 0.64809365193697555, 0.74012419157855436, 0.82000198597390295,
    0.88641552700440107, 0.93827455200273280, 0.97472855597130947, 0.99518721999702131,
);
const GL24_WEIGHTS: array<f32, 12> = array<f32, 12>(
    0.12793819534675224, 0.12583745634682839, 0.12167047292780335, 0.11550566805372561,
    0.10744427011596562, 0.09761865210411390, 0.08619016153195322, 0.07334648141108027,
    0.05929858491543666, 0.04427743881741968, 0.02853138862893381, 0.01234122979998733,
);

// rule: node i (ascending) of the n-point rule (8, 12 or 24) and its weight.
fn rule(n: u32, i: u32) -> vec2<f32> {
    let half = n / 2u;
    var k = i - half;
    var sign = 1.0;
    if i < half {
        k = half - 1u - i;
        sign = -1.0;
    }
    if n == RULE_NODES_ANISO {
        return vec2<f32>(sign * GL24_NODES[k], GL24_WEIGHTS[k]);
    }
    if n == DIFFUSE_NODES {
        return vec2<f32>(sign * GL8_NODES[k], GL8_WEIGHTS[k]);
    }
    return vec2<f32>(sign * GL12_NODES[k], GL12_WEIGHTS[k]);
}

// rule_nodes: the specular lobe's nodes for a material of roughness alpha.
fn rule_nodes(alpha: vec2<f32>) -> u32 {
    if alpha.x == alpha.y {
        return RULE_NODES;
    }
    return RULE_NODES_ANISO;
}

// mirror: the mirror direction of v about the normal, where a glossy lobe peaks.
fn mirror(v: vec3<f32>) -> vec3<f32> {
    return vec3<f32>(-v.x, -v.y, v.z);
}

// A convex region of directions: great circles n·ω ≥ 0 and at most one cap
// |ω − axis|² ≤ 2 depth (cap.w = depth; < 0: none).
struct Bounds {
    planes: array<vec3<f32>, 5>,
    count: u32,
    cap: vec4<f32>,
}

// Bounds::above: the horizon and a cap (cap.w < 0: the whole upper hemisphere).
fn bounds_above(cap: vec4<f32>) -> Bounds {
    var b: Bounds;
    b.count = 0u;
    b.cap = cap;
    bounds_push(&b, vec3<f32>(0.0, 0.0, 1.0));
    return b;
}

// Bounds::push: the great circle of inward normal n.
fn bounds_push(b: ptr<function, Bounds>, n: vec3<f32>) {
    let at = (*b).count;
    if at < MAX_PLANES {
        // Written at a constant index (see "Writes" above).
        for (var k = 0u; k < MAX_PLANES; k++) {
            if k == at {
                (*b).planes[k] = n;
            }
        }
        (*b).count = at + 1u;
    }
}

// Bounds::contains: whether x is in the closed region.
fn bounds_contains(b: Bounds, x: vec3<f32>) -> bool {
    for (var k = 0u; k < b.count; k++) {
        if dot(b.planes[k], x) < 0.0 {
            return false;
        }
    }
    if b.cap.w >= 0.0 {
        let off = x - b.cap.xyz;
        return 0.5 * dot(off, off) <= b.cap.w;
    }
    return true;
}

// Bounds::meridian: [lo, hi] of T = tan(u/2) where the meridian cos u c + sin u d is inside
// every bound (hi ≤ lo: nowhere).
fn bounds_meridian(b: Bounds, c: vec3<f32>, d: vec3<f32>) -> vec2<f32> {
    var out = vec2<f32>(0.0, T_INFINITE);
    for (var k = 0u; k < b.count; k++) {
        let m = plane_meridian(dot(b.planes[k], c), dot(b.planes[k], d));
        out = vec2<f32>(max(out.x, m.x), min(out.y, m.y));
    }
    if b.cap.w >= 0.0 {
        let m = cap_meridian(c, d, b.cap.xyz, b.cap.w);
        out = vec2<f32>(max(out.x, m.x), min(out.y, m.y));
    }
    return out;
}

// plane_meridian: a cos u + b sin u ≥ 0 on u ∈ [0, π] in T (src/light/polar.rs).
fn plane_meridian(a: f32, b: f32) -> vec2<f32> {
    let r = sqrt(a * a + b * b);
    if r == 0.0 {
        return vec2<f32>(0.0, T_INFINITE);
    }
    if a >= 0.0 {
        var root = (r + b) / a;
        if b < 0.0 {
            root = a / (r - b);
        }
        return vec2<f32>(0.0, root);
    }
    var root = (r - b) / -a;
    if b > 0.0 {
        root = -a / (r + b);
    }
    return vec2<f32>(root, T_INFINITE);
}

// cap_meridian: |ω(u) − a|² ≤ 2 depth in T, a quadratic whose coefficients do not cancel for
// a small cap (src/light/polar.rs).
fn cap_meridian(c: vec3<f32>, d: vec3<f32>, axis: vec3<f32>, depth: f32) -> vec2<f32> {
    let off = c - axis;
    let q = 0.5 * dot(off, off);
    let b = dot(axis - c, d);
    let lead = max(2.0 - depth - q, 1e-30);
    let roots = quadratic_roots(lead, -2.0 * b, q - depth);
    if roots.z == 0.0 {
        return vec2<f32>(1.0, 0.0);
    }
    return vec2<f32>(max(roots.x, 0.0), roots.y);
}

// quadratic_roots: x₁ ≤ x₂ of a x² + b x + c (a > 0) by the form that does not cancel;
// z = 0 where there are none.
fn quadratic_roots(a: f32, b: f32, c: f32) -> vec3<f32> {
    let disc = b * b - 4.0 * a * c;
    if disc < 0.0 {
        return vec3<f32>(0.0);
    }
    let s = -0.5 * (b + select(-sqrt(disc), sqrt(disc), b >= 0.0));
    if s == 0.0 {
        return vec3<f32>(0.0, 0.0, 1.0);
    }
    let x1 = c / s;
    let x2 = s / a;
    return vec3<f32>(min(x1, x2), max(x1, x2), 1.0);
}

// A lobe's ellipse at the pole: the tangent basis b1, b2 and s's columns in it.
struct Lobe {
    b1: vec3<f32>,
    b2: vec3<f32>,
    s0: vec2<f32>,
    s1: vec2<f32>,
}

// tangent_basis: the tangent plane at unit c, its first vector horizontal (x where c is
// vertical).
fn tangent_basis(c: vec3<f32>) -> mat2x3<f32> {
    var b1 = vec3<f32>(1.0, 0.0, 0.0);
    let z = cross(vec3<f32>(0.0, 0.0, 1.0), c);
    if dot(z, z) > 0.0 {
        b1 = normalize(z);
    }
    return mat2x3<f32>(b1, cross(c, b1));
}

// Lobe::round: width 2 every way (u = 2t), for the diffuse lobe.
fn lobe_round(c: vec3<f32>) -> Lobe {
    let basis = tangent_basis(c);
    return Lobe(basis[0], basis[1], vec2<f32>(2.0, 0.0), vec2<f32>(0.0, 2.0));
}

// Lobe::specular: GGX's lobe about the pole c, √(A Aᵀ + dist² I) (src/light/polar.rs).
fn lobe_specular(c: vec3<f32>, v: vec3<f32>, alpha: vec2<f32>) -> Lobe {
    let basis = tangent_basis(c);
    let b1 = basis[0];
    let b2 = basis[1];
    let lx = vec3<f32>(alpha.x, 0.0, 0.0) * (2.0 * v.z) + vec3<f32>(0.0, 0.0, 2.0 * v.x * alpha.x);
    let ly = vec3<f32>(0.0, alpha.y, 0.0) * (2.0 * v.z) + vec3<f32>(0.0, 0.0, 2.0 * v.y * alpha.y);
    let a0 = vec2<f32>(dot(b1, lx), dot(b2, lx));
    let a1 = vec2<f32>(dot(b1, ly), dot(b2, ly));
    let off = c - mirror(v);
    let dist2 = dot(off, off);
    let floor = 1e-8;
    let m00 = a0.x * a0.x + a1.x * a1.x + dist2 + floor;
    let m11 = a0.y * a0.y + a1.y * a1.y + dist2 + floor;
    let m01 = a0.x * a0.y + a1.x * a1.y;
    let root_det = sqrt(max(m00 * m11 - m01 * m01, 0.0));
    let scale = 1.0 / sqrt(m00 + m11 + 2.0 * root_det);
    return Lobe(b1, b2, vec2<f32>(m00 + root_det, m01) * scale, vec2<f32>(m01, m11 + root_det) * scale);
}

// Lobe::within: each principal width combined with the region's chord through its middle.
fn lobe_within(lobe: Lobe, b: Bounds, middle: vec3<f32>) -> Lobe {
    let m00 = lobe.s0.x;
    let m01 = lobe.s0.y;
    let m11 = lobe.s1.y;
    let half_trace = 0.5 * (m00 + m11);
    let root = sqrt(0.25 * (m00 - m11) * (m00 - m11) + m01 * m01);
    let w1 = half_trace + root;
    let w2 = max(half_trace - root, 1e-12);
    let sc = sincos_precise(0.5 * atan2_full(2.0 * m01, m00 - m11));
    let e1 = vec2<f32>(sc.y, sc.x);
    let e2 = vec2<f32>(-e1.y, e1.x);
    let c1 = lobe_chord(lobe, b, middle, e1);
    let c2 = lobe_chord(lobe, b, middle, e2);
    let u1 = 1.0 / sqrt(1.0 / (w1 * w1) + 1.0 / (c1 * c1));
    let u2 = 1.0 / sqrt(1.0 / (w2 * w2) + 1.0 / (c2 * c2));
    let s0 = e1 * (u1 * e1.x) + e2 * (u2 * e2.x);
    let s1 = e1 * (u1 * e1.y) + e2 * (u2 * e2.y);
    return Lobe(lobe.b1, lobe.b2, s0, s1);
}

// The region's chord through `middle` along ±e (e in the pole's tangent basis).
fn lobe_chord(lobe: Lobe, b: Bounds, middle: vec3<f32>, e: vec2<f32>) -> f32 {
    var sum = 0.0;
    for (var k = 0u; k < 2u; k++) {
        let t = (lobe.b1 * e.x + lobe.b2 * e.y) * select(1.0, -1.0, k == 1u);
        let d = toward(middle, middle + t);
        if dot(d, d) > 0.0 {
            let m = bounds_meridian(b, middle, d);
            if m.y > m.x {
                sum += 2.0 * atan_precise(m.y);
            }
        }
    }
    return max(sum, 1e-9);
}

// Lobe::angle_of: the ellipse's angle τ of the tangent t (s⁻¹ t's polar angle, by its
// adjugate).
fn lobe_angle_of(lobe: Lobe, t: vec3<f32>) -> f32 {
    let p = vec2<f32>(dot(t, lobe.b1), dot(t, lobe.b2));
    let w = vec2<f32>(lobe.s1.y * p.x - lobe.s1.x * p.y, -lobe.s0.y * p.x + lobe.s0.x * p.y);
    return atan2_full(w.y, w.x);
}

// A region ready to integrate: bounds, pole and the tangents there where pieces end.
struct Polar {
    bounds: Bounds,
    pole: vec3<f32>,
    cuts: array<vec3<f32>, 16>,
    count: u32,
}

// Polar::new: cut at the `turns` (2 or 4) equal turns of the pole's tangent basis.
fn polar_new(bounds: Bounds, pole: vec3<f32>, turns: u32) -> Polar {
    var p: Polar;
    p.bounds = bounds;
    p.pole = pole;
    p.count = 0u;
    let basis = tangent_basis(pole);
    polar_cut_both(&p, basis[0]);
    if turns > 2u {
        polar_cut_both(&p, basis[1]);
    }
    return p;
}

// Polar::cut_foot: a cut toward where the great circle of unit normal n passes nearest the
// pole.
fn polar_cut_foot(p: ptr<function, Polar>, n: vec3<f32>) {
    let t = (*p).pole * dot((*p).pole, n) - n;
    if dot(t, t) > 0.0 {
        polar_cut(p, normalize(t));
    }
}

// toward: the unit tangent at c toward x along their great circle (0 where x is within
// SAME_DIRECTION of c).
fn toward(c: vec3<f32>, x: vec3<f32>) -> vec3<f32> {
    let t = x - c * dot(x, c);
    if dot(t, t) > SAME_DIRECTION * SAME_DIRECTION {
        return normalize(t);
    }
    return vec3<f32>(0.0);
}

// Directions closer than this are one (src/light/polar.rs SAME_DIRECTION).
const SAME_DIRECTION: f32 = 1e-6;

// Polar::cut_toward: a cut at the tangent toward x.
fn polar_cut_toward(p: ptr<function, Polar>, x: vec3<f32>) {
    let t = toward((*p).pole, x);
    if dot(t, t) > 0.0 {
        polar_cut(p, t);
    }
}

// Polar::cut_both: cuts at t (along the pole's tangent plane) and −t.
fn polar_cut_both(p: ptr<function, Polar>, t: vec3<f32>) {
    let along = t - (*p).pole * dot(t, (*p).pole);
    if dot(along, along) > 0.0 {
        let u = normalize(along);
        polar_cut(p, u);
        polar_cut(p, -u);
    }
}

fn polar_cut(p: ptr<function, Polar>, t: vec3<f32>) {
    let at = (*p).count;
    if at < MAX_CUTS {
        // Written at a constant index (see "Writes" above).
        for (var k = 0u; k < MAX_CUTS; k++) {
            if k == at {
                (*p).cuts[k] = t;
            }
        }
        (*p).count = at + 1u;
    }
}

// One lobe toward l: the specular (which = 0) or the diffuse (1).
fn lobe_value(v: vec3<f32>, l: vec3<f32>, alpha: vec2<f32>, f0: f32, which: u32) -> f32 {
    let lobes = exact_lobes(v, l, alpha, f0);
    return select(lobes.y, lobes.x, which == 0u);
}

// Polar::integral: ∫ g dω over the region about its pole, stretched to `lobe`, n × n nodes a
// piece; g the lobe `which` of v, alpha, f0 (src/light/polar.rs).
fn polar_integral(p: Polar, lobe: Lobe, n: u32, v: vec3<f32>, alpha: vec2<f32>, f0: f32, which: u32) -> f32 {
    // The cuts' angles, each written at a constant index (see "Writes" above).
    var angles: array<f32, 16>;
    for (var k = 0u; k < MAX_CUTS; k++) {
        let t = p.cuts[k];
        angles[k] = atan2_full(dot(t, lobe.b2), dot(t, lobe.b1));
    }
    let count = max(p.count, 1u);
    if p.count == 0u {
        angles[0] = 0.0;
    }
    let det = lobe.s0.x * lobe.s1.y - lobe.s1.x * lobe.s0.y;
    var total = 0.0;
    for (var k = 0u; k < count; k++) {
        let start = angles[k];
        let width = piece_width(angles, count, k);
        if width > PIECE_MIN_WIDTH && piece_meets(p, lobe, start + 0.5 * width) {
            total += polar_piece(p, lobe, det, vec2<f32>(start, start + width), n, v, alpha, f0, which);
        }
    }
    return total;
}

// The width of the piece from cut k to the next cut counterclockwise, in the order of
// (angle, index): the pieces Polar::integral takes between its sorted cuts, without a sort's
// writes; a cut tied with one before it starts a piece of width 0, which is dropped.
fn piece_width(angles: array<f32, 16>, count: u32, k: u32) -> f32 {
    let start = angles[k];
    var width = 2.0 * PI;
    for (var j = 0u; j < MAX_CUTS; j++) {
        if j < count && j != k {
            var d = angles[j] - start;
            if d < 0.0 || (d == 0.0 && j < k) {
                d += 2.0 * PI;
            }
            width = min(width, d);
        }
    }
    return width;
}

// Pieces narrower than this are dropped: two cuts at one direction (src/light/polar.rs).
const PIECE_MIN_WIDTH: f32 = 1e-6;

// The tangent at the pole of azimuth phi (any real) in the lobe's basis.
fn azimuth(lobe: Lobe, phi: f32) -> vec3<f32> {
    let sc = sincos_precise(wrapped(phi));
    return lobe.b1 * sc.y + lobe.b2 * sc.x;
}

// phi brought into [−π, π] (sincos_precise's range).
fn wrapped(phi: f32) -> f32 {
    var x = phi;
    if x > PI {
        x -= 2.0 * PI;
    }
    if x < -PI {
        x += 2.0 * PI;
    }
    return x;
}

// Whether the meridian at azimuth phi meets the region.
fn piece_meets(p: Polar, lobe: Lobe, phi: f32) -> bool {
    let m = bounds_meridian(p.bounds, p.pole, azimuth(lobe, phi));
    return m.y > m.x;
}

// One piece [ab.x, ab.y] of azimuth: n nodes in τ, each meridian's n nodes in t. Every call
// of these functions is a copy of them where a driver inlines (Mesa's do, all of them), and a
// pipeline compiles for as long as its copies take: each shape calls the rule from one place.
fn polar_piece(
    p: Polar,
    lobe: Lobe,
    det: f32,
    ab: vec2<f32>,
    n: u32,
    v: vec3<f32>,
    alpha: vec2<f32>,
    f0: f32,
    which: u32,
) -> f32 {
    let tau0 = lobe_angle_of(lobe, azimuth(lobe, ab.x));
    var span = lobe_angle_of(lobe, azimuth(lobe, ab.y)) - tau0;
    if span < 0.0 {
        span += 2.0 * PI;
    }
    var total = 0.0;
    for (var i = 0u; i < n; i++) {
        let node = rule(n, i);
        let sc = sincos_precise(wrapped(tau0 + 0.5 * span * (node.x + 1.0)));
        let q = lobe.s0 * sc.y + lobe.s1 * sc.x;
        let r = length(q);
        let d = (lobe.b1 * q.x + lobe.b2 * q.y) / r;
        let m = bounds_meridian(p.bounds, p.pole, d);
        if m.y > m.x {
            let t0 = atan_precise(2.0 * m.x / r);
            let t1 = atan_precise(2.0 * m.y / r);
            let w_phi = 0.5 * span * node.y * det / (r * r) * 0.5 * (t1 - t0);
            var radial = 0.0;
            for (var j = 0u; j < n; j++) {
                radial += radial_node(p.pole, d, r, t0, t1, rule(n, j), v, alpha, f0, which);
            }
            total += w_phi * radial;
        }
    }
    return total;
}

// One radial node: tan(u/2) = (r/2) tan t, weighted by sin u du/dt.
fn radial_node(
    c: vec3<f32>,
    d: vec3<f32>,
    r: f32,
    t0: f32,
    t1: f32,
    node: vec2<f32>,
    v: vec3<f32>,
    alpha: vec2<f32>,
    f0: f32,
    which: u32,
) -> f32 {
    let sc = sincos_precise(t0 + 0.5 * (t1 - t0) * (node.x + 1.0));
    let tan_t = sc.x / sc.y;
    let half = 0.5 * r * tan_t;
    let h2 = half * half;
    let cos_u = (1.0 - h2) / (1.0 + h2);
    let sin_u = 2.0 * half / (1.0 + h2);
    let du_dt = r * (1.0 + tan_t * tan_t) / (1.0 + h2);
    return node.y * sin_u * du_dt * lobe_value(v, c * cos_u + d * sin_u, alpha, f0, which);
}
