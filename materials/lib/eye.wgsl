// Eye geometry (materials/eye): where the view ray through a point of the
// eyeball meets the iris, by refraction through a spherical cornea (the
// reference) or by the parallax approximation (fast, and the seed's offset).
// Pure functions of their arguments, no bindings: tests/physics/eye.rs evaluates them
// on the GPU with a compute kernel and checks them against an f64 ray trace.
//
// The eye's frame: the eyeball is the unit sphere at the origin, +z is the
// optical axis (out of the eye), +y up, +x to the viewer's right when the eye
// looks at them. A point of the eyeball's mesh is given by its unit
// object-space normal, which on a sphere is its position in this frame; a
// front-projected eye uv (the bust's) is (0.5 + x/2, 0.5 - y/2).
//
// The anterior segment: the iris is the plane z = z_iris through the limbus,
// the circle of radius `iris_radius` where the iris meets the eyeball
// (z_iris = sqrt(1 - iris_radius^2)). The cornea is the spherical cap over
// that circle rising `height` above the plane at the axis (the anterior
// chamber depth): sphere radius (r^2 + h^2) / (2 h) through the limbus, as
// in Le Grand's schematic eye with the cornea's thickness ignored (one
// refracting surface, aqueous humour behind it).

struct EyeCornea {
    // z of the iris plane.
    z_iris: f32,
    // z of the cornea sphere's centre, and its radius.
    centre_z: f32,
    radius: f32,
}

// The iris point seen through a point of the eyeball, and the cornea there.
struct EyeLookup {
    // xy of the point of the iris plane the view ray reaches (eye frame);
    // for a ray that does not cross the cornea, the eyeball point itself.
    iris: vec2<f32>,
    // Unit outward normal of the surface the ray enters: the cornea, or the
    // eyeball (the sclera) where the ray misses the cornea.
    normal: vec3<f32>,
    // 1 where the ray crosses the cornea, 0 on the sclera.
    through_cornea: f32,
}

// The cap's geometry from the limbus radius and the cornea's height, both in
// eyeball radii; both are clamped to where the cap exists (radius in
// [0.05, 0.95], height > 0.01).
fn eye_cornea(iris_radius: f32, height: f32) -> EyeCornea {
    let r = clamp(iris_radius, 0.05, 0.95);
    let h = max(height, 0.01);
    let z_iris = sqrt(1.0 - r * r);
    let radius = (r * r + h * h) / (2.0 * h);
    return EyeCornea(z_iris, z_iris + h - radius, radius);
}

// Height of the cornea above the iris plane at distance `rho` from the axis
// (0 at and beyond the limbus).
fn eye_cornea_height(c: EyeCornea, rho: f32) -> f32 {
    let z = c.centre_z + sqrt(max(c.radius * c.radius - rho * rho, 0.0));
    return max(z - c.z_iris, 0.0);
}

// Unit outward normal of the cornea sphere at the point above (x, y).
fn eye_cornea_normal(c: EyeCornea, xy: vec2<f32>) -> vec3<f32> {
    let z = sqrt(max(c.radius * c.radius - dot(xy, xy), 0.0));
    return vec3<f32>(xy, z) / c.radius;
}

// Where the refracted ray meets the iris plane. `t` is the refracted unit
// direction; below a 1e-4 downward component (total internal reflection
// returns zero, grazing rays) the ray is taken as reaching the limbus.
fn eye_to_iris_plane(start: vec3<f32>, t: vec3<f32>, z_iris: f32) -> vec2<f32> {
    let down = max(-t.z, 1e-4);
    return start.xy + t.xy * ((start.z - z_iris) / down);
}

// Reference: the view line through eyeball point `p` (unit, eye frame) along
// `v` (unit, towards the viewer) intersected with the cornea sphere (the
// intersection nearest the viewer; the mesh is the eyeball, the cornea bulges
// out of it, so the hit may lie in front of `p`), refracted there
// (Snell, air -> aqueous humour of index `ior`) and carried to the iris
// plane. A line that misses the cap sees the sclera at `p`, as does a point
// on the back of the eyeball (p.z <= 0), which the front projection would
// otherwise map onto the iris.
fn eye_refracted(p: vec3<f32>, v: vec3<f32>, c: EyeCornea, ior: f32) -> EyeLookup {
    let centre = vec3<f32>(0.0, 0.0, c.centre_z);
    let o = p - centre;
    // |o + s v|^2 = R^2 with |v| = 1: s = -b +- sqrt(b^2 - (|o|^2 - R^2)).
    let b = dot(o, v);
    let disc = b * b - (dot(o, o) - c.radius * c.radius);
    let s = -b + sqrt(max(disc, 0.0));
    let hit = p + s * v;
    if p.z <= 0.0 || disc <= 0.0 || hit.z < c.z_iris {
        return EyeLookup(p.xy, p, 0.0);
    }
    let n = (hit - centre) / c.radius;
    let t = refract(-v, n, 1.0 / max(ior, 1.0));
    return EyeLookup(eye_to_iris_plane(hit, t, c.z_iris), n, 1.0);
}

// Fast: the parallax approximation, refraction to first order in the angles
// (paraxial). The cornea rises d = z_cornea - p.z over the eyeball point p,
// so the view line enters it near e = p.xy + d v.xy (to first order); there
// the cornea stands h above the iris plane with normal m, and
// refract(-v, m, 1/ior) ~ -v / ior - (1 - 1/ior) m for small angles, its
// z ~ -1, so
//   iris = e - h (v.xy / ior + (1 - 1/ior) m.xy):
// the seed's offset (view xy times a depth) with the depth the reference's
// geometry gives, plus the cornea's magnification (the m.xy term, zero on
// the axis). Exact at normal incidence on the axis; the error grows with the
// angle (tests/physics/eye.rs). Outside the limbus: the sclera at p.
fn eye_parallax(p: vec3<f32>, v: vec3<f32>, c: EyeCornea, ior: f32) -> EyeLookup {
    let limbus = sqrt(1.0 - c.z_iris * c.z_iris);
    let rho = length(p.xy);
    if p.z <= 0.0 || rho >= limbus {
        return EyeLookup(p.xy, p, 0.0);
    }
    let inv_ior = 1.0 / max(ior, 1.0);
    let d = c.z_iris + eye_cornea_height(c, rho) - p.z;
    // The entry point, kept inside the limbus.
    let e_raw = p.xy + d * v.xy;
    let e = e_raw * min(1.0, limbus / max(length(e_raw), 1e-6));
    let h = eye_cornea_height(c, length(e));
    let m = eye_cornea_normal(c, e);
    let iris = e - h * (v.xy * inv_ior + m.xy * (1.0 - inv_ior));
    return EyeLookup(iris, m, 1.0);
}

// The seed's offset (seed 004 sec. 5), in eye uv: uv + height * view_os.xy
// with the y component negated. Object y runs up and the eye uv's v down, so
// in the eye frame the offset is height * view.xy in both axes: a positive
// height lifts the iris towards the viewer, a negative one sinks it.
fn eye_seed_uv(uv: vec2<f32>, v: vec3<f32>, height: f32) -> vec2<f32> {
    return uv + height * vec2<f32>(v.x, -v.y);
}

// Eye frame xy <-> front-projected eye uv (the bust's: iris at (0.5, 0.5)).
fn eye_uv_from_xy(xy: vec2<f32>) -> vec2<f32> {
    return vec2<f32>(0.5 + 0.5 * xy.x, 0.5 - 0.5 * xy.y);
}

fn eye_xy_from_uv(uv: vec2<f32>) -> vec2<f32> {
    return vec2<f32>(2.0 * uv.x - 1.0, 1.0 - 2.0 * uv.y);
}
