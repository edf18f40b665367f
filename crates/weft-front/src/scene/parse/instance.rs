//! One `[[instances]]` entry: its name, material, preset, tier request
//! (`auto` with its budget and screen size), keywords, written parameters,
//! `dynamic` list, mesh (built-in or a glTF primitive), material variant,
//! render-state overrides and transform; and the check that names are unique.

use super::*;

/// The instance's name (for the duplicate check) and, when it has a name
/// and a material, the instance.
pub(super) type ParsedInstance<'a, 'i> = (
    Option<Spanned<String>>,
    Option<(InstanceDecl, Vec<WrittenParam<'a, 'i>>)>,
);

pub(super) fn parse_instance<'a, 'i>(item: &'a Value<'i>, cx: &mut Cx) -> ParsedInstance<'a, 'i> {
    let Some(mut t) = Table::new(item, "an [[instances]] entry", cx) else {
        return (None, None);
    };
    let name = t.string("name", cx);
    if let Some(n) = &name {
        t.what = format!("instance `{n}`");
    }
    t.check_keys(INSTANCE_KEYS, cx);
    // Errors about the instance as a whole point at its name, or its first key.
    let at = t.get("name").map_or_else(
        || {
            t.entries()
                .next()
                .map_or_else(|| t.span.clone(), |(_, span, _)| span)
        },
        |v| v.span(),
    );
    match &name {
        None if t.get("name").is_none() => cx.error_with_note(
            "missing-key",
            "an [[instances]] entry has no `name`",
            at.clone(),
            "in this instance",
            "give every instance a unique lower_snake_case `name`",
        ),
        Some(n) if !is_scene_name(n) => cx.error_with_note(
            "bad-name",
            format!("instance name `{n}` is not a lower_snake_case name"),
            at.clone(),
            "names the instance in the scene metadata",
            "use lower case letters, digits and underscores, starting with a letter",
        ),
        _ => {}
    }
    let material = required_string(
        &t,
        "material",
        &at,
        "name a material folder of the materials root, e.g. `material = \"standard\"`",
        cx,
    );
    let preset = t.string("preset", cx).map(|value| Spanned {
        value,
        span: t.span_of("preset"),
    });
    let tier = parse_tier(&t, cx);
    let keywords = parse_keywords(&t, cx);
    let params = written_params(&t, cx);
    let dynamic = parse_dynamic(&t, cx);
    let mesh = parse_mesh(&t, &at, cx);
    let vertex_inputs = parse_vertex_inputs(&t, "vertex_inputs", cx).map(|value| Spanned {
        value,
        span: t.span_of("vertex_inputs"),
    });
    let transform = parse_transform(&t, cx);
    let variant = parse_variant(&t, cx);
    let overrides = parse_overrides(&t, cx);
    let Some(name) = name else {
        return (None, None);
    };
    let written_name = Spanned {
        value: name.clone(),
        span: at.clone(),
    };
    let Some(material) = material else {
        return (Some(written_name), None);
    };
    let decl = InstanceDecl {
        name,
        span: t.span.clone(),
        name_span: at,
        material,
        preset,
        tier,
        keywords,
        dynamic,
        // A missing or unknown mesh is reported; the instance is still
        // resolved (the scene fails anyway) so that one run shows everything.
        mesh: mesh.unwrap_or(Spanned {
            value: MeshSpec::Builtin(BuiltinMesh::Sphere),
            span: t.span.clone(),
        }),
        vertex_inputs,
        transform,
        variant,
        overrides,
    };
    (Some(written_name), Some((decl, params)))
}

/// `double_sided = true` and `blend = "alpha"` (any blend mode but opaque).
fn parse_overrides(t: &Table, cx: &mut Cx) -> InstanceOverrides {
    let double_sided = t.boolean("double_sided", cx).unwrap_or(false);
    let blend = t.string("blend", cx).and_then(|name| {
        let modes: Vec<&str> = weft_meta::BlendMode::ALL
            .iter()
            .filter(|m| **m != weft_meta::BlendMode::Opaque)
            .map(|m| m.name())
            .collect();
        let found = weft_meta::BlendMode::ALL
            .into_iter()
            .find(|m| m.name() == name && *m != weft_meta::BlendMode::Opaque);
        if found.is_none() {
            cx.error_with_note(
                "unknown-value",
                format!("`blend = \"{name}\"` is not a blend mode an instance may set"),
                t.span_of("blend"),
                "not one of the blend modes",
                suggestion_listing(&name, &modes, "blend modes"),
            );
        }
        found
    });
    InstanceOverrides {
        double_sided,
        blend,
        sampler: parse_sampler(t, cx),
    }
}

/// `sampler = { address_mode_u = "clamp_to_edge", mag_filter = "nearest",
/// mipmaps = false, … }`.
fn parse_sampler(t: &Table, cx: &mut Cx) -> Option<SamplerOverride> {
    use weft_meta::{AddressMode, FilterMode};
    let v = t.get("sampler")?;
    let table = Table::new(v, "`sampler`", cx)?;
    table.check_keys(SAMPLER_KEYS, cx);
    let address = |key, cx: &mut Cx| table.one_of(key, &AddressMode::ALL, AddressMode::name, cx);
    let filter = |key, cx: &mut Cx| table.one_of(key, &FilterMode::ALL, FilterMode::name, cx);
    Some(SamplerOverride {
        address_mode_u: address("address_mode_u", cx),
        address_mode_v: address("address_mode_v", cx),
        mag_filter: filter("mag_filter", cx),
        min_filter: filter("min_filter", cx),
        mipmap_filter: filter("mipmap_filter", cx),
        mipmaps: table.boolean("mipmaps", cx),
    })
}

/// `tier`, with `error_budget` and `screen_size` for `auto` (and only then).
fn parse_tier(t: &Table, cx: &mut Cx) -> Spanned<TierRequest> {
    let span = t.span_of("tier");
    let tier = t.string("tier", cx);
    let budget = t.number("error_budget", cx);
    let size = t.integer("screen_size", cx);
    if tier.as_deref() != Some(AUTO_TIER) {
        for key in ["error_budget", "screen_size"] {
            if let Some(key_span) = t.key_span(key) {
                cx.error_with_note(
                    "unknown-key",
                    format!("`{key}` only applies to `tier = \"{AUTO_TIER}\"`"),
                    key_span,
                    "not used with this tier",
                    format!(
                        "write `tier = \"{AUTO_TIER}\"` to let the build choose the tier, or remove `{key}`"
                    ),
                );
            }
        }
        let value = tier.map_or(TierRequest::Default, TierRequest::Named);
        return Spanned { value, span };
    }
    let missing = |cx: &mut Cx, key: &str, note: &str| {
        cx.error_with_note(
            "missing-key",
            format!("`tier = \"{AUTO_TIER}\"` needs `{key}` in {}", t.what),
            span.clone(),
            format!("`{key}` missing"),
            note,
        );
    };
    if t.get("error_budget").is_none() {
        missing(
            cx,
            "error_budget",
            "the largest mean FLIP error against the reference tier the instance may show, in (0, 1], e.g. `error_budget = 0.05`",
        );
    }
    if t.get("screen_size").is_none() {
        missing(
            cx,
            "screen_size",
            "the instance's size on screen in pixels (16 to 4096), e.g. `screen_size = 256`",
        );
    }
    let budget = budget.filter(|b| {
        let ok = *b > 0.0 && *b <= 1.0;
        if !ok {
            cx.error_with_note(
                "out-of-range",
                format!("`error_budget` of {} must be in (0, 1]", t.what),
                t.span_of("error_budget"),
                format!("{b} is not in (0, 1]"),
                "a mean FLIP error: 0 would allow no difference at all, 1 any",
            );
        }
        ok
    });
    let size = size.filter(|s| {
        let ok = SCREEN_SIZE_RANGE.contains(s);
        if !ok {
            cx.error(
                "out-of-range",
                format!(
                    "`screen_size` of {} must be between {} and {} pixels",
                    t.what,
                    SCREEN_SIZE_RANGE.start(),
                    SCREEN_SIZE_RANGE.end()
                ),
                t.span_of("screen_size"),
                format!("{s} is outside that range"),
            );
        }
        ok
    });
    let value = match (budget, size) {
        (Some(error_budget), Some(size)) => TierRequest::Auto {
            error_budget,
            screen_size: size as u32,
        },
        // Already reported; the scene does not resolve.
        _ => TierRequest::Default,
    };
    Spanned { value, span }
}

/// `keywords = { NAME = "value" }`; `true`/`false` read as `on`/`off`, as in presets.
fn parse_keywords(t: &Table, cx: &mut Cx) -> Vec<(Spanned<String>, Spanned<String>)> {
    let Some(table) = t
        .get("keywords")
        .and_then(|v| Table::new(v, format!("`keywords` of {}", t.what), cx))
    else {
        return Vec::new();
    };
    let mut out = Vec::new();
    for (name, name_span, v) in table.entries() {
        let value = match v.get_ref() {
            DeValue::String(s) => s.to_string(),
            DeValue::Boolean(b) => if *b { "on" } else { "off" }.to_string(),
            other => {
                type_error(
                    cx,
                    &format!("keyword `{name}` of {}", t.what),
                    "a value name (or true/false for a toggle)",
                    other,
                    v.span(),
                );
                continue;
            }
        };
        out.push((
            Spanned {
                value: name.to_string(),
                span: name_span,
            },
            Spanned {
                value,
                span: v.span(),
            },
        ));
    }
    out
}

fn written_params<'a, 'i>(t: &Table<'a, 'i>, cx: &mut Cx) -> Vec<WrittenParam<'a, 'i>> {
    t.get("params")
        .and_then(|v| Table::new(v, format!("`params` of {}", t.what), cx))
        .map(|table| {
            table
                .entries()
                .map(|(name, name_span, value)| WrittenParam {
                    name,
                    name_span,
                    value,
                })
                .collect()
        })
        .unwrap_or_default()
}

/// `dynamic`, each name once.
fn parse_dynamic(t: &Table, cx: &mut Cx) -> Vec<Spanned<String>> {
    let mut out: Vec<Spanned<String>> = Vec::new();
    for (value, span) in t.strings("dynamic", cx).unwrap_or_default() {
        if let Some(first) = out.iter().find(|d| d.value == value) {
            let first = first.span.clone();
            let d = cx.diags.error(
                "duplicate",
                format!("`{value}` is listed twice in `dynamic` of {}", t.what),
                cx.file,
                span,
                "again here",
            );
            d.labels
                .push(Label::secondary(cx.file, first).with_message("first listed here"));
            continue;
        }
        out.push(Spanned { value, span });
    }
    out
}

fn parse_mesh(t: &Table, at: &Span, cx: &mut Cx) -> Option<Spanned<MeshSpec>> {
    let names = BuiltinMesh::ALL.map(BuiltinMesh::name);
    let note = format!(
        "built-in meshes: {}; or a glTF mesh: `mesh = {{ gltf = \"x.glb\", mesh = 0, primitive = 0 }}`",
        names.join(", ")
    );
    if let Some(v) = t.get("mesh")
        && matches!(v.get_ref(), DeValue::Table(_))
    {
        let table = Table::new(v, "`mesh`", cx)?;
        table.check_keys(GLTF_MESH_KEYS, cx);
        let file = required_string(&table, "gltf", &v.span(), &note, cx)?;
        let index = |key: &str, cx: &mut Cx| -> Option<usize> {
            let n = table.integer(key, cx).unwrap_or(0);
            match usize::try_from(n) {
                Ok(n) => Some(n),
                Err(_) => {
                    cx.error(
                        "out-of-range",
                        format!("`{key}` of `mesh` must be ≥ 0"),
                        table.span_of(key),
                        "an index into the glTF file",
                    );
                    None
                }
            }
        };
        let mesh = index("mesh", cx)?;
        let primitive = index("primitive", cx)?;
        let node = match table.get("node") {
            None => None,
            Some(_) => Some(index("node", cx)?),
        };
        let uv_transform = match table.numbers("uv_transform", cx) {
            None => None,
            Some(n) if n.len() == 6 && n.iter().all(|x| fits_f32(*x)) => {
                Some(std::array::from_fn(|i| n[i]))
            }
            Some(_) => {
                cx.error(
                    "bad-type",
                    "`uv_transform` of `mesh` must be 6 finite numbers [a, b, c, d, e, f]",
                    table.span_of("uv_transform"),
                    "uv0 becomes (a u + b v + c, d u + e v + f)",
                );
                return None;
            }
        };
        return Some(Spanned {
            value: MeshSpec::Gltf {
                file: PathBuf::from(file.value),
                mesh,
                primitive,
                uv_transform,
                node,
            },
            span: v.span(),
        });
    }
    let name = required_string(t, "mesh", at, &note, cx)?;
    match BuiltinMesh::from_name(&name.value) {
        Some(value) => Some(Spanned {
            value: MeshSpec::Builtin(value),
            span: name.span,
        }),
        None => {
            cx.error_with_note(
                "unknown-mesh",
                format!("unknown mesh `{}`", name.value),
                name.span,
                "not a built-in mesh",
                suggestion_listing(&name.value, &names, "built-in meshes"),
            );
            None
        }
    }
}

/// `variant = { name = "…", replaces = "…" }`.
fn parse_variant(t: &Table, cx: &mut Cx) -> Option<Spanned<InstanceVariant>> {
    let v = t.get("variant")?;
    let table = Table::new(v, "`variant`", cx)?;
    table.check_keys(VARIANT_KEYS, cx);
    let note = "a material variant's instance: `variant = { name = \"<variant>\", replaces = \"<instance>\" }`";
    let name = required_string(&table, "name", &v.span(), note, cx)?;
    let replaces = required_string(&table, "replaces", &v.span(), note, cx)?;
    Some(Spanned {
        value: InstanceVariant {
            name: name.value,
            replaces: replaces.value,
        },
        span: v.span(),
    })
}

/// `matrix = [16 numbers]`: object -> world, column-major.
fn parse_matrix(t: &Table, cx: &mut Cx) -> Option<[f64; 16]> {
    let span = t.span_of("matrix");
    let numbers = t.numbers("matrix", cx)?;
    if numbers.len() != 16 || !numbers.iter().all(|x| fits_f32(*x)) {
        cx.error(
            "bad-type",
            format!(
                "`matrix` of {} must be 16 finite numbers (column-major)",
                t.what
            ),
            span,
            "object -> world, columns x, y, z, translation",
        );
        return None;
    }
    Some(std::array::from_fn(|i| numbers[i]))
}

fn parse_transform(t: &Table, cx: &mut Cx) -> Transform {
    let mut transform = Transform::default();
    if t.get("matrix").is_some() {
        if let Some(key) = ["translation", "rotation", "scale"]
            .into_iter()
            .find(|k| t.get(k).is_some())
        {
            cx.error(
                "conflicting-keys",
                format!("{} has both `matrix` and `{key}`", t.what),
                t.span_of(key),
                "give either `matrix` or translation / rotation / scale",
            );
        }
        transform.matrix = parse_matrix(t, cx);
        return transform;
    }
    transform.translation = vec3(t, "translation", cx).unwrap_or(transform.translation);
    transform.rotation_degrees = vec3(t, "rotation", cx).unwrap_or(transform.rotation_degrees);
    let scale = match t.get("scale").map(|v| v.get_ref()) {
        None => None,
        Some(DeValue::Array(_)) => vec3(t, "scale", cx),
        Some(DeValue::Integer(_) | DeValue::Float(_)) => match t.number("scale", cx) {
            Some(s) if !fits_f32(s) => {
                f32_range_error("scale", t, t.span_of("scale"), cx);
                None
            }
            s => s.map(|s| [s; 3]),
        },
        Some(other) => {
            type_error(
                cx,
                &format!("`scale` of {}", t.what),
                "a number or 3 numbers [x, y, z]",
                other,
                t.span_of("scale"),
            );
            None
        }
    };
    if let Some(scale) = scale {
        if scale.iter().all(|s| *s > 0.0) {
            transform.scale = scale;
        } else {
            cx.error(
                "out-of-range",
                format!("`scale` of {} must be positive", t.what),
                t.span_of("scale"),
                "every component must be > 0",
            );
        }
    }
    transform
}

pub(super) fn check_unique_names(names: &[Spanned<String>], cx: &mut Cx) {
    for (i, name) in names.iter().enumerate() {
        let Some(first) = names.iter().take(i).find(|x| x.value == name.value) else {
            continue;
        };
        let d = cx.diags.error(
            "duplicate",
            format!("two instances are named `{}`", name.value),
            cx.file,
            name.span.clone(),
            "second instance with this name",
        );
        d.labels
            .push(Label::secondary(cx.file, first.span.clone()).with_message("first one here"));
        d.notes.push(
            "instance names are unique in a scene: they name the instance in the scene metadata"
                .into(),
        );
    }
}
