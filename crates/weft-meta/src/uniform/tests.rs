//! The encoder's bytes written out by hand, type spellings round-tripped,
//! and values read back from scene JSON.

use super::*;
use crate::{UniformLayout, UniformMember};

/// Little-endian f32 bytes, written out by hand from the IEEE bits.
fn f(bits: u32) -> [u8; 4] {
    bits.to_le_bytes()
}

fn member(name: &str, ty: UniformType, offset: u32, size: u32) -> UniformMember {
    UniformMember {
        name: name.into(),
        ty,
        offset,
        size,
        align: 4,
        parameter: None,
        encoding: None,
        description: None,
    }
}

/// Every parameter kind with a uniform member, through the kind's own
/// type and encoding, against bytes written by hand.
#[test]
fn every_kind_encodes_to_hand_written_bytes() {
    let cases: Vec<(ParamKind, u32, ParamValue, Vec<u8>)> = vec![
        // 1.5 = 0x3FC00000.
        (
            ParamKind::Float,
            0,
            ParamValue::Float(1.5),
            vec![0x00, 0x00, 0xC0, 0x3F],
        ),
        // -2 as i32: two's complement.
        (
            ParamKind::Int,
            0,
            ParamValue::Int(-2),
            vec![0xFE, 0xFF, 0xFF, 0xFF],
        ),
        (
            ParamKind::Bool,
            0,
            ParamValue::Bool(true),
            vec![0x01, 0x00, 0x00, 0x00],
        ),
        (
            ParamKind::Bool,
            0,
            ParamValue::Bool(false),
            vec![0x00, 0x00, 0x00, 0x00],
        ),
        // 1.0 = 0x3F800000, 2.0 = 0x40000000.
        (
            ParamKind::Vec2,
            0,
            ParamValue::Vector(vec![1.0, 2.0]),
            [f(0x3F80_0000), f(0x4000_0000)].concat(),
        ),
        // vec3: 12 bytes (the 16-byte alignment is the layout's business).
        (
            ParamKind::Vec3,
            0,
            ParamValue::Vector(vec![0.5, -1.0, 0.0]),
            [f(0x3F00_0000), f(0xBF80_0000), f(0)].concat(),
        ),
        (
            ParamKind::Vec4,
            0,
            ParamValue::Vector(vec![0.25, 4.0, -0.5, 8.0]),
            [
                f(0x3E80_0000),
                f(0x4080_0000),
                f(0xBF00_0000),
                f(0x4100_0000),
            ]
            .concat(),
        ),
        // sRGB 1.0 and 0.0 are linear 1.0 and 0.0; alpha 0.5 as is; sRGB
        // 0.5 is linear 0.21404114 = f32 0x3E5B2D9A (rounded;
        // Python: struct.pack("<f", ((0.5 + 0.055) / 1.055) ** 2.4)).
        (
            ParamKind::Color,
            0,
            ParamValue::Color {
                edited: vec![1.0, 0.0, 0.5, 0.5],
                hdr: false,
            },
            [f(0x3F80_0000), f(0), f(0x3E5B_2D9A), f(0x3F00_0000)].concat(),
        ),
        // HDR colours are linear as edited; three components: alpha 1.
        (
            ParamKind::Color,
            0,
            ParamValue::Color {
                edited: vec![2.0, 0.5, 0.0],
                hdr: true,
            },
            [f(0x4000_0000), f(0x3F00_0000), f(0), f(0x3F80_0000)].concat(),
        ),
        (
            ParamKind::Color,
            0,
            ParamValue::LinearColor([0.25, 0.5, 1.0, 1.0]),
            [
                f(0x3E80_0000),
                f(0x3F00_0000),
                f(0x3F80_0000),
                f(0x3F80_0000),
            ]
            .concat(),
        ),
        // 5 samples: array<vec4<f32>, 2>, sample i at [i / 4][i % 4], the tail 0.
        (
            ParamKind::Curve,
            5,
            ParamValue::Curve(vec![0.0, 0.25, 0.5, 0.75, 1.0]),
            [
                f(0),
                f(0x3E80_0000),
                f(0x3F00_0000),
                f(0x3F40_0000),
                f(0x3F80_0000),
                f(0),
                f(0),
                f(0),
            ]
            .concat(),
        ),
    ];
    for (kind, samples, value, expected) in cases {
        let ty = kind.uniform_type(samples).expect("a uniform kind");
        let encoding = kind.encoding().expect("a uniform kind");
        let v = encoding.value(&value).expect("fits the kind");
        let bytes = encode(&ty, &v).expect("encodes");
        assert_eq!(bytes, expected, "{kind:?} {value:?}");
        assert_eq!(Some(bytes.len() as u32), ty.size(), "{kind:?}");
    }
    // A texture's tiling member.
    let v = MemberEncoding::TilingOffset
        .value(&ParamValue::TilingOffset(TILING_OFFSET_DEFAULT))
        .unwrap();
    assert_eq!(
        encode(&TILING_OFFSET_TYPE, &v).unwrap(),
        [f(0x3F80_0000), f(0x3F80_0000), f(0), f(0)].concat()
    );
    // The kinds bound as textures have no member.
    for kind in [ParamKind::Texture2d, ParamKind::Cube, ParamKind::Gradient] {
        assert_eq!(kind.uniform_type(4), None);
        assert_eq!(kind.encoding(), None);
    }
}

#[test]
fn values_that_do_not_fit_are_errors() {
    assert!(
        MemberEncoding::I32
            .value(&ParamValue::Int(1 << 40))
            .is_err()
    );
    assert!(MemberEncoding::F32.value(&ParamValue::Bool(true)).is_err());
    assert!(encode(&UniformType::F32, &UniformValue::I32(1)).is_err());
    assert!(encode(&UniformType::vec_f32(3), &UniformValue::F32s(vec![1.0; 4])).is_err());
    let curve = ParamKind::Curve.uniform_type(8).unwrap();
    assert!(encode(&curve, &UniformValue::F32s(vec![0.0; 4])).is_err());
    assert!(encode(&curve, &UniformValue::F32s(vec![0.0; 9])).is_err());
}

#[test]
fn matrices_pad_their_columns() {
    let m3: Vec<f64> = (1..=9).map(f64::from).collect();
    let bytes = encode(&UniformType::mat_f32(3, 3), &UniformValue::F32s(m3)).unwrap();
    assert_eq!(bytes.len(), 48);
    assert_eq!(&bytes[12..16], &[0; 4]);
    assert_eq!(&bytes[16..20], &4f32.to_le_bytes());
    let m4: Vec<f64> = (0..16).map(f64::from).collect();
    let bytes = encode(&UniformType::mat_f32(4, 4), &UniformValue::F32s(m4)).unwrap();
    assert_eq!(&bytes[60..64], &15f32.to_le_bytes());
}

#[test]
fn pack_writes_at_the_layout_offsets() {
    let layout = UniformLayout {
        struct_name: "WeftMaterial".into(),
        size: 32,
        align: 16,
        members: vec![
            member("tint", UniformType::vec_f32(3), 0, 12),
            member("roughness", UniformType::F32, 12, 4),
            member("layers", UniformType::I32, 16, 4),
        ],
    };
    let bytes = pack::<EncodeError>(&layout, |m| {
        Ok(Some(match m.name.as_str() {
            "tint" => UniformValue::F32s(vec![1.0, 0.0, 0.0]),
            "roughness" => UniformValue::F32(0.5),
            _ => UniformValue::I32(3),
        }))
    })
    .unwrap();
    let mut expected = vec![0u8; 32];
    expected[0..4].copy_from_slice(&f(0x3F80_0000));
    expected[12..16].copy_from_slice(&f(0x3F00_0000));
    expected[16..20].copy_from_slice(&[3, 0, 0, 0]);
    assert_eq!(bytes, expected);
    let short = UniformLayout { size: 8, ..layout };
    let e = pack::<EncodeError>(&short, |m| {
        Ok((m.name == "tint").then(|| UniformValue::F32s(vec![0.0; 3])))
    })
    .unwrap_err();
    assert!(e.0.contains("overruns"), "{e}");
}

#[test]
fn types_serialise_to_the_wgsl_spelling() {
    for s in [
        "f32",
        "i32",
        "u32",
        "f16",
        "vec2<f32>",
        "vec3<f32>",
        "vec4<f32>",
        "vec4<f16>",
        "mat4x4<f32>",
        "mat3x2<f32>",
        "array<vec4<f32>, 9>",
        "array<array<f32, 4>, 2>",
        "array<f32>",
        "atomic<u32>",
        "WeftFrame",
    ] {
        let t: UniformType = s.parse().unwrap();
        assert_eq!(t.to_string(), s);
        let json = serde_json::to_string(&t).unwrap();
        assert_eq!(json, format!("\"{s}\""));
        assert_eq!(serde_json::from_str::<UniformType>(&json).unwrap(), t);
    }
    for bad in [
        "vec5<f32>",
        "array<vec4<f32>,9>",
        "vec4f",
        "mat4<f32>",
        "",
        "a b",
    ] {
        assert!(bad.parse::<UniformType>().is_err(), "{bad}");
    }
    assert_eq!(
        ParamKind::Curve.uniform_type(33).unwrap().to_string(),
        "array<vec4<f32>, 9>"
    );
    assert_eq!(UniformType::vec_f32(3).size(), Some(12));
    assert_eq!(UniformType::mat_f32(4, 4).size(), Some(64));
    assert_eq!(
        UniformType::array(UniformType::vec_f32(4), 9).size(),
        Some(144)
    );
}

#[test]
fn json_values_are_read_by_the_member_type() {
    use serde_json::json;
    let curve = ParamKind::Curve.uniform_type(6).unwrap();
    assert_eq!(
        UniformValue::from_json(&curve, &json!([[1, 2, 3, 4], [5, 6, 0, 0]])).unwrap(),
        UniformValue::F32s(vec![1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 0.0, 0.0])
    );
    assert_eq!(
        UniformValue::from_json(&UniformType::U32, &json!(true)).unwrap(),
        UniformValue::U32(1)
    );
    assert!(UniformValue::from_json(&UniformType::I32, &json!(1.5)).is_err());
    for v in [
        UniformValue::F32(0.1),
        UniformValue::I32(-3),
        UniformValue::U32(1),
        UniformValue::F32s(vec![0.1, 0.2]),
    ] {
        let ty = match v {
            UniformValue::F32(_) => UniformType::F32,
            UniformValue::I32(_) => UniformType::I32,
            UniformValue::U32(_) => UniformType::U32,
            UniformValue::F32s(_) => UniformType::vec_f32(2),
        };
        assert_eq!(UniformValue::from_json(&ty, &v.to_json()).unwrap(), v);
    }
}
