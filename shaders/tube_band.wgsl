// A tube's exact rule (docs/design.md §1.15), mirroring src/light/tube/band.rs (with
// region.rs's silhouette and horizon corners) by name: the silhouette as a band in longitude
// and latitude about the segment's plane, its cuts and the stretched Gauss–Legendre nodes.
// Composed after tube_light.wgsl (Tube, TubeShading), sphere_light.wgsl, rect_light.wgsl,
// disk_light.wgsl and polar.wgsl, as it; the Rust side is src/gpu/light/tube_band.rs.

// The silhouette in longitude ψ about o (the normal of the segment's plane with the point)
// and latitude λ: its frame (u at ψ = 0, w at π/2, o), each end ball's cap (its centre's
// longitude and angular radius), the band's tangent longitudes, axis and k = r/√(ρ² − r²)
// where the point is outside the cylinder (k < 0 where not), the longitudes it spans, and the
// region.rs pieces horizon_corners reads: each cap's axis and depth and the four inward
// normals of the quadrilateral between the caps.
struct Band {
    u: vec3<f32>,
    w: vec3<f32>,
    o: vec3<f32>,
    caps: vec4<f32>,
    at: vec2<f32>,
    e: vec3<f32>,
    k: f32,
    range: vec2<f32>,
    cap_a: vec4<f32>,
    cap_b: vec4<f32>,
    n0: vec3<f32>,
    n1: vec3<f32>,
    n2: vec3<f32>,
    n3: vec3<f32>,
}

// wrap: x brought into (−π, π] (x within 3π of it).
fn wrap(x: f32) -> f32 {
    var y = x;
    if y > PI {
        y -= 2.0 * PI;
    }
    if y <= -PI {
        y += 2.0 * PI;
    }
    return y;
}

// The longitude of x in the frame (u, w).
fn band_lon(u: vec3<f32>, w: vec3<f32>, x: vec3<f32>) -> f32 {
    return atan2_full(dot(x, w), dot(x, u));
}

// A cap seen from the origin: its axis and depth 1 − cos σ = sin²σ/(1 + cos σ) (region.rs).
fn cap_of_ball(p: vec3<f32>, r: f32) -> vec4<f32> {
    let d = length(p);
    let sin = min(r / d, 1.0);
    return vec4<f32>(p / d, sin * sin / (1.0 + sqrt(max(1.0 - sin * sin, 0.0))));
}

// Band::hemisphere: what a point inside the capsule sees, longitude about z.
fn band_hemisphere() -> Band {
    let x = vec3<f32>(1.0, 0.0, 0.0);
    let y = vec3<f32>(0.0, 1.0, 0.0);
    let z = vec3<f32>(0.0, 0.0, 1.0);
    let none = vec4<f32>(z, 0.0);
    return Band(x, y, z, vec4<f32>(0.0), vec2<f32>(-PI, PI), z, T_INFINITE, vec2<f32>(-PI, PI),
        none, none, z, z, z, z);
}

// Band::of with Silhouette::of: the band of a tube whose silhouette does not hold the origin.
fn band_of(t: Tube) -> Band {
    let r = t.radius;
    let e = tube_axis(t);
    let len = tube_length(t);
    let c = cross(t.a, t.b);
    var o: vec3<f32>;
    if length(c) > 1e-6 * length(t.a) * length(t.b) {
        o = normalize(c);
    } else {
        // Seen end-on (or a ball): any plane through the axis.
        var any = t.a;
        if len > 0.0 {
            any = e;
        }
        o = orthonormal_pair(normalize(any))[0];
    }
    let u = normalize(t.a);
    let w = cross(o, u);
    let psi_b = band_lon(u, w, t.b);
    let sin_a = min(r / length(t.a), 1.0);
    let sin_b = min(r / length(t.b), 1.0);
    let sigma_a = atan2_precise(sin_a, sqrt(max(1.0 - sin_a * sin_a, 0.0)));
    let sigma_b = atan2_precise(sin_b, sqrt(max(1.0 - sin_b * sin_b, 0.0)));
    let caps = vec4<f32>(0.0, sigma_a, psi_b, sigma_b);
    let range = vec2<f32>(min(-sigma_a, psi_b - sigma_b), max(sigma_a, psi_b + sigma_b));
    var band = Band(u, w, o, caps, vec2<f32>(0.0), e, -1.0, range,
        cap_of_ball(t.a, r), cap_of_ball(t.b, r), o, o, o, o);
    let across = t.a - e * dot(t.a, e);
    let rho = length(across);
    if rho > r * (1.0 + 1e-6) && len > 0.0 {
        let out = across / rho;
        let side = cross(e, out);
        let cos = r / rho;
        let sin = sqrt(max((1.0 - cos) * (1.0 + cos), 0.0));
        band.n0 = out * cos + side * sin;
        band.n1 = out * cos - side * sin;
        let ta0 = normalize(t.a - band.n0 * r);
        let ta1 = normalize(t.a - band.n1 * r);
        let tb0 = normalize(t.b - band.n0 * r);
        let tb1 = normalize(t.b - band.n1 * r);
        band.n2 = chord_normal(ta0, ta1, tb0 + tb1);
        band.n3 = chord_normal(tb0, tb1, ta0 + ta1);
        let lon_a = wrap(band_lon(u, w, ta0));
        let lon_b = psi_b + wrap(band_lon(u, w, tb0) - psi_b);
        band.at = vec2<f32>(min(lon_a, lon_b), max(lon_a, lon_b));
        band.k = r / sqrt((rho - r) * (rho + r));
    }
    return band;
}

// The great circle through p and q as a plane's normal, toward `toward` (region.rs chord).
fn chord_normal(p: vec3<f32>, q: vec3<f32>, toward: vec3<f32>) -> vec3<f32> {
    let m = cross(p, q);
    if dot(m, m) <= 0.0 {
        return vec3<f32>(0.0);
    }
    let n = normalize(m);
    return select(n, -n, dot(n, toward) < 0.0);
}

// Band::along: the direction at longitude psi, latitude 0.
fn band_along(b: Band, psi: f32) -> vec3<f32> {
    let sc = sincos_precise(wrapped(psi));
    return b.u * sc.y + b.w * sc.x;
}

// Band::longitude: the longitude of x within π of the range's middle.
fn band_longitude(b: Band, x: vec3<f32>) -> f32 {
    let mid = 0.5 * (b.range.x + b.range.y);
    return mid + wrap(band_lon(b.u, b.w, x) - mid);
}

// cap_half_width: sin Λ = √(sin(σ − off) sin(σ + off)) / cos off (band.rs).
fn cap_half_width(sigma: f32, off: f32) -> f32 {
    let lo = sincos_precise(sigma - off);
    let hi = sincos_precise(sigma + off);
    let s = min(sqrt(max(lo.x * hi.x, 0.0)) / sincos_precise(off).y, 1.0);
    return atan2_precise(s, sqrt(max((1.0 - s) * (1.0 + s), 0.0)));
}

// Band::half_width: Λ(ψ), the silhouette's half-width in latitude (0 outside it).
fn band_half_width(b: Band, psi: f32) -> f32 {
    if b.k >= 0.0 && psi >= b.at.x && psi <= b.at.y {
        return atan_precise(b.k * length(cross(band_along(b, psi), b.e)));
    }
    var half = 0.0;
    for (var c = 0u; c < 2u; c++) {
        let centre = b.caps[2u * c];
        let sigma = b.caps[2u * c + 1u];
        let off = abs(psi - centre);
        if off < sigma {
            half = max(half, cap_half_width(sigma, off));
        }
    }
    return half;
}

// Inside cap k (region.rs horizon_corners' inside_cap).
fn band_inside_cap(b: Band, x: vec3<f32>, k: u32) -> bool {
    let cap = select(b.cap_a, b.cap_b, k == 1u);
    let d = x - cap.xyz;
    return 0.5 * dot(d, d) < cap.w;
}

// Inside the quadrilateral: strictly, or but for plane `on` (4: none), which x lies on.
fn band_in_quad(b: Band, x: vec3<f32>, strict: bool, on: u32) -> bool {
    if b.k < 0.0 {
        return false;
    }
    let n = array<vec3<f32>, 4>(b.n0, b.n1, b.n2, b.n3);
    for (var k = 0u; k < 4u; k++) {
        let s = dot(n[k], x);
        if (strict && !(s > 0.0)) || (!strict && k != on && s < 0.0) {
            return false;
        }
    }
    return true;
}

// MAX_CUTS of a tube's longitudes: the range's 2 ends, the caps' 4 extents, their 2
// crossings, 2 tangent longitudes, MAX_HORIZON_CORNERS (4) and the peak.
const TUBE_MAX_CUTS: u32 = 15u;

// The cuts of the band's rule: Band::cuts with horizon_corners' longitudes and, where
// `peak`, the peak's, each clamped to the range (unsorted: band_integral orders them).
struct Cuts {
    at: array<f32, 15>,
    count: u32,
}

fn cuts_push(c: ptr<function, Cuts>, x: f32, range: vec2<f32>) {
    let v = clamp(x, range.x, range.y);
    for (var k = 0u; k < TUBE_MAX_CUTS; k++) {
        if k == (*c).count {
            (*c).at[k] = v;
        }
    }
    (*c).count = min((*c).count + 1u, TUBE_MAX_CUTS);
}

fn band_cuts(b: Band, peak: f32, with_peak: bool) -> Cuts {
    var c: Cuts;
    c.count = 0u;
    let r = b.range;
    cuts_push(&c, r.x, r);
    cuts_push(&c, r.y, r);
    let pa = b.caps.x;
    let sa = b.caps.y;
    let pb = b.caps.z;
    let sb = b.caps.w;
    cuts_push(&c, pa - sa, r);
    cuts_push(&c, pa + sa, r);
    cuts_push(&c, pb - sb, r);
    cuts_push(&c, pb + sb, r);
    // Where the caps' circles cross: cos σA cos(ψ − ψB) = cos σB cos(ψ − ψA).
    let ca = sincos_precise(sa).y;
    let cb = sincos_precise(sb).y;
    let ra = sincos_precise(wrapped(pa));
    let rb = sincos_precise(wrapped(pb));
    let p = ca * rb.y - cb * ra.y;
    let q = ca * rb.x - cb * ra.x;
    if p != 0.0 || q != 0.0 {
        let x = atan2_full(-p, q);
        let mid = 0.5 * (r.x + r.y);
        cuts_push(&c, mid + wrap(x - mid), r);
        cuts_push(&c, mid + wrap(x + PI - mid), r);
    }
    if b.k >= 0.0 {
        cuts_push(&c, b.at.x, r);
        cuts_push(&c, b.at.y, r);
    }
    band_push_corners(&c, b);
    if with_peak {
        cuts_push(&c, peak, r);
    }
    return c;
}

// horizon_corners (region.rs): where each cap's circle and each tangent great circle meets
// the horizon on the union's boundary, as longitudes.
fn band_push_corners(c: ptr<function, Cuts>, b: Band) {
    var found = 0u;
    for (var k = 0u; k < 2u; k++) {
        let cap = select(b.cap_a, b.cap_b, k == 1u);
        let cos_sigma = 1.0 - cap.w;
        let h = length(cap.xy);
        if h > 0.0 && h >= abs(cos_sigma) {
            let mid = atan2_full(cap.y, cap.x);
            let half = acos_precise(clamp(cos_sigma / h, -1.0, 1.0));
            for (var s = 0u; s < 2u; s++) {
                let sc = sincos_precise(wrapped(mid + select(-half, half, s == 1u)));
                let x = vec3<f32>(sc.y, sc.x, 0.0);
                if !band_inside_cap(b, x, 1u - k) && !band_in_quad(b, x, true, 4u) && found < 4u {
                    cuts_push(c, band_longitude(b, x), b.range);
                    found += 1u;
                }
            }
        }
    }
    if b.k < 0.0 {
        return;
    }
    for (var k = 0u; k < 2u; k++) {
        let n = select(b.n0, b.n1, k == 1u);
        let m = cross(n, vec3<f32>(0.0, 0.0, 1.0));
        if dot(m, m) > 0.0 {
            for (var s = 0u; s < 2u; s++) {
                let x = select(normalize(m), -normalize(m), s == 1u);
                if band_in_quad(b, x, false, k) && !band_inside_cap(b, x, 0u)
                    && !band_inside_cap(b, x, 1u) && found < 4u {
                    cuts_push(c, band_longitude(b, x), b.range);
                    found += 1u;
                }
            }
        }
    }
}

// The next cut above cut k in the order of (value, index), or k's own where none is: the
// pieces band_integral takes between the sorted cuts, without a sort's writes.
fn next_cut(c: Cuts, k: u32) -> f32 {
    let start = c.at[k];
    var next = start;
    var found = false;
    for (var j = 0u; j < TUBE_MAX_CUTS; j++) {
        if j < c.count && j != k {
            let x = c.at[j];
            let after = x > start || (x == start && j > k);
            if after && (!found || x < next) {
                next = x;
                found = true;
            }
        }
    }
    return next;
}

// Pieces narrower than this are dropped (band.rs PIECE_MIN, for f32 angles).
const TUBE_PIECE_MIN: f32 = 1e-6;

// One node of Gauss–Legendre's n over [a, b], stretched toward `anchor` (an end of it) by
// `width` where width > 0 (x = anchor ± width tan t): its place and weight (band.rs nodes).
fn band_node(n: u32, i: u32, ab: vec2<f32>, anchor: f32, width: f32) -> vec2<f32> {
    let g = rule(n, i);
    if width <= 0.0 {
        return vec2<f32>(ab.x + 0.5 * (ab.y - ab.x) * (g.x + 1.0), 0.5 * (ab.y - ab.x) * g.y);
    }
    var far = ab.y;
    var sign = 1.0;
    if abs(anchor - ab.x) > abs(anchor - ab.y) {
        far = ab.x;
        sign = -1.0;
    }
    let top = atan_precise(abs(far - anchor) / width);
    let sc = sincos_precise(0.5 * top * (g.x + 1.0));
    let tan = sc.x / sc.y;
    return vec2<f32>(anchor + sign * width * tan, 0.5 * top * g.y * width * (1.0 + tan * tan));
}

// around: [a, b] split at `at` where it lies inside — part `half` (0 or 1) of it and the end
// to stretch toward; a second part of no width where `at` is outside.
fn around(at: f32, ab: vec2<f32>, half: u32) -> vec3<f32> {
    if at > ab.x && at < ab.y {
        if half == 0u {
            return vec3<f32>(ab.x, at, at);
        }
        return vec3<f32>(at, ab.y, at);
    }
    if half == 0u {
        return vec3<f32>(ab.x, ab.y, clamp(at, ab.x, ab.y));
    }
    return vec3<f32>(ab.y, ab.y, ab.y);
}

// latitudes (band.rs): [lo, hi] inside the silhouette and above the surface at longitude psi
// (hi ≤ lo where none is).
fn band_latitudes(b: Band, psi: f32, d: vec3<f32>) -> vec2<f32> {
    let half = band_half_width(b, psi);
    if half <= 0.0 || (d.z == 0.0 && b.o.z == 0.0) {
        return vec2<f32>(0.0);
    }
    let l0 = atan2_full(b.o.z, d.z);
    return vec2<f32>(max(-half, l0 - 0.5 * PI), min(half, l0 + 0.5 * PI));
}

// band_integral: lobe `which` (0 specular, 1 diffuse) over the silhouette above the surface
// by the band's rule, n nodes a dimension and piece, the specular stretched toward `peak`
// (longitude, latitude) by `width` radians (band.rs band_integral).
fn band_integral(b: Band, c: Cuts, n: u32, peak: vec2<f32>, width: f32, s: TubeShading, which: u32) -> f32 {
    let stretch = which == 0u;
    let cos_peak = max(sincos_precise(peak.y).y, 0.05);
    var total = 0.0;
    for (var k = 0u; k < TUBE_MAX_CUTS; k++) {
        if k >= c.count {
            break;
        }
        let piece = vec2<f32>(c.at[k], next_cut(c, k));
        for (var h = 0u; h < 2u; h++) {
            var part = vec3<f32>(piece, 0.0);
            var w_psi = 0.0;
            if stretch {
                part = around(peak.x, piece, h);
                w_psi = (width + abs(peak.x - part.z)) / cos_peak;
            } else if h == 1u {
                break;
            }
            if part.y - part.x > TUBE_PIECE_MIN {
                for (var i = 0u; i < n; i++) {
                    let node = band_node(n, i, part.xy, part.z, w_psi);
                    total += node.y * band_meridian(b, node.x, n, peak.y, width, stretch, s, which);
                }
            }
        }
    }
    return total;
}

// One meridian of band_integral: ∫ g cos λ dλ at longitude psi.
fn band_meridian(b: Band, psi: f32, n: u32, peak: f32, width: f32, stretch: bool, s: TubeShading, which: u32) -> f32 {
    let d = band_along(b, psi);
    let lat = band_latitudes(b, psi, d);
    var total = 0.0;
    for (var h = 0u; h < 2u; h++) {
        var part = vec3<f32>(lat, 0.0);
        var w_lambda = 0.0;
        if stretch {
            part = around(peak, lat, h);
            w_lambda = width + abs(peak - part.z);
        } else if h == 1u {
            break;
        }
        if part.y - part.x > TUBE_PIECE_MIN {
            for (var j = 0u; j < n; j++) {
                let node = band_node(n, j, part.xy, part.z, w_lambda);
                let sc = sincos_precise(node.x);
                let x = d * sc.y + b.o * sc.x;
                total += node.y * sc.y * lobe_value(s.pixel.v, x, s.pixel.alpha, s.pixel.f0, which);
            }
        }
    }
    return total;
}

// tube_band: both lobes over the silhouette above the surface by the band's rule at the
// renders' nodes, the specular stretched toward the mirror direction by 2 max(αx, αy).
fn tube_band(s: TubeShading) -> vec2<f32> {
    var b = band_hemisphere();
    if !tube_encloses_origin(s.tube) {
        b = band_of(s.tube);
    }
    let focus = mirror(s.pixel.v);
    let sin_lat = clamp(dot(focus, b.o), -1.0, 1.0);
    let peak = vec2<f32>(
        band_longitude(b, focus),
        atan2_full(sin_lat, sqrt(max((1.0 - sin_lat) * (1.0 + sin_lat), 0.0))),
    );
    let width = 2.0 * max(s.pixel.alpha.x, s.pixel.alpha.y);
    var out = vec2<f32>(0.0);
    // Both lobes from one call of the rule (see polar_piece).
    for (var which = 0u; which < 2u; which++) {
        let cuts = band_cuts(b, peak.x, which == 0u);
        let n = select(DIFFUSE_NODES, rule_nodes(s.pixel.alpha), which == 0u);
        out[which] = band_integral(b, cuts, n, peak, width, s, which);
    }
    return out;
}
