//! 4×4 transforms of glTF nodes (column-major, as glTF stores them) in f64,
//! and each node's world matrix in the file's default state (its own TRS or
//! matrix, no animation applied).

pub type Mat4 = [[f64; 4]; 4];

pub const IDENTITY: Mat4 = [
    [1.0, 0.0, 0.0, 0.0],
    [0.0, 1.0, 0.0, 0.0],
    [0.0, 0.0, 1.0, 0.0],
    [0.0, 0.0, 0.0, 1.0],
];

pub fn mul(a: &Mat4, b: &Mat4) -> Mat4 {
    // Column-major: (a b)[c][r] = Σ_k a[k][r] b[c][k].
    std::array::from_fn(|c| std::array::from_fn(|r| (0..4).map(|k| a[k][r] * b[c][k]).sum()))
}

pub fn transform_point(m: &Mat4, p: [f64; 3]) -> [f64; 3] {
    std::array::from_fn(|r| m[0][r] * p[0] + m[1][r] * p[1] + m[2][r] * p[2] + m[3][r])
}

pub fn transform_vector(m: &Mat4, v: [f64; 3]) -> [f64; 3] {
    std::array::from_fn(|r| m[0][r] * v[0] + m[1][r] * v[1] + m[2][r] * v[2])
}

pub fn normalize(v: [f64; 3]) -> Option<[f64; 3]> {
    let len = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
    (len.is_finite() && len > 1e-12).then(|| v.map(|x| x / len))
}

/// `v` as it is when unit length (glTF requires unit normals and tangents:
/// kept bit for bit), normalised when not, `fallback` when it has no direction.
pub fn unit_or(v: [f32; 3], fallback: [f32; 3]) -> [f32; 3] {
    let len = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
    if (len - 1.0).abs() < 1e-4 {
        v
    } else if len.is_finite() && len > 1e-12 {
        v.map(|x| x / len)
    } else {
        fallback
    }
}

/// The matrix that carries normals with `m` (its upper 3×3's cofactors: the
/// inverse transpose times the determinant, whose scale normalising
/// removes), and the determinant's sign (a mirror flips the bitangent).
pub fn normal_matrix(m: &Mat4) -> ([[f64; 3]; 3], f64) {
    let a = |c: usize, r: usize| m[c][r];
    // cof[c][r]: column c, row r of the cofactor matrix of the 3×3 block.
    let cof: [[f64; 3]; 3] = std::array::from_fn(|c| {
        std::array::from_fn(|r| {
            let (c1, c2) = ((c + 1) % 3, (c + 2) % 3);
            let (r1, r2) = ((r + 1) % 3, (r + 2) % 3);
            a(c1, r1) * a(c2, r2) - a(c2, r1) * a(c1, r2)
        })
    });
    let det: f64 = (0..3).map(|r| a(0, r) * cof[0][r]).sum();
    (cof, det)
}

/// Each node's world matrix (parents' transforms applied), walking down
/// from the nodes no node names as a child: linear in the node count
/// however deep the trees. A node no such walk reaches (one in a cycle) has
/// `None`; the scene walk reports cycles.
pub fn world_matrices(document: &gltf::Document) -> Vec<Option<Mat4>> {
    let nodes: Vec<gltf::Node> = document.nodes().collect();
    let mut has_parent = vec![false; nodes.len()];
    for node in &nodes {
        for child in node.children() {
            has_parent[child.index()] = true;
        }
    }
    let local = |n: &gltf::Node| -> Mat4 { n.transform().matrix().map(|c| c.map(f64::from)) };
    let mut world: Vec<Option<Mat4>> = vec![None; nodes.len()];
    let mut stack: Vec<(usize, Mat4)> = nodes
        .iter()
        .filter(|n| !has_parent[n.index()])
        .map(|n| (n.index(), local(n)))
        .collect();
    while let Some((i, m)) = stack.pop() {
        // A node reached twice (shared by two parents) keeps its first.
        if world[i].is_some() {
            continue;
        }
        world[i] = Some(m);
        for child in nodes[i].children() {
            stack.push((child.index(), mul(&m, &local(&child))));
        }
    }
    world
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A chain of 50 000 nodes, each 1 along x from its parent: the walk
    /// is linear (one step per parent link would be 1.25 × 10⁹ steps).
    #[test]
    fn world_matrices_of_a_deep_chain() {
        let n = 50_000;
        let nodes: Vec<serde_json::Value> = (0..n)
            .map(|i| {
                let mut node = serde_json::json!({ "translation": [1.0, 0.0, 0.0] });
                if i + 1 < n {
                    node["children"] = serde_json::json!([i + 1]);
                }
                node
            })
            .collect();
        let json = serde_json::json!({
            "asset": { "version": "2.0" }, "nodes": nodes,
            "scenes": [ { "nodes": [0] } ],
        });
        let gltf = gltf::Gltf::from_slice(&serde_json::to_vec(&json).unwrap()).unwrap();
        let worlds = world_matrices(&gltf.document);
        assert_eq!(worlds.len(), n);
        let last = worlds[n - 1].expect("reached");
        assert_eq!(last[3][0], n as f64);
    }

    #[test]
    fn normals_follow_a_non_uniform_scale() {
        // Scale x by 2: the cofactors of diag(2, 1, 1) are diag(1, 2, 2),
        // so the normal (1, 1, 0) of the plane x = y becomes (1, 2, 0),
        // the normal of the scaled plane x = 2y.
        let mut m = IDENTITY;
        m[0][0] = 2.0;
        let (cof, det) = normal_matrix(&m);
        let n = [1.0, 1.0, 0.0];
        let t: [f64; 3] = std::array::from_fn(|r| (0..3).map(|c| cof[c][r] * n[c]).sum());
        assert_eq!(t, [1.0, 2.0, 0.0]);
        assert_eq!(det, 2.0);
        // A tangent (1, -1, 0) of that plane, moved by m: (2, -1, 0), still
        // perpendicular to the moved normal.
        let tangent = transform_vector(&m, [1.0, -1.0, 0.0]);
        assert_eq!(tangent.iter().zip(&t).map(|(a, b)| a * b).sum::<f64>(), 0.0);
    }
}
