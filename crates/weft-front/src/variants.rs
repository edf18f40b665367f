//! The static variant space: every tier crossed with every value of every
//! `static` keyword, minus the combinations `[variants].exclude` removes.

use crate::model::Material;
use weft_meta::{Condition, KeywordMode};

/// One point of the variant space.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct VariantKey {
    pub tier: usize,
    /// (keyword index in `Material::keywords`, value index), static keywords only, in declaration order.
    pub keywords: Vec<(usize, usize)>,
}

impl VariantKey {
    /// File stem and id: `<tier>.<keyword>-<value>…`, lower case.
    pub fn id(&self, m: &Material) -> String {
        let mut id = m.tiers.values[self.tier].clone();
        for &(k, v) in &self.keywords {
            let kw = &m.keywords[k];
            id.push('.');
            id.push_str(&kw.name.to_lowercase());
            id.push('-');
            id.push_str(&kw.values[v]);
        }
        id
    }

    /// The value a condition subject has in this variant (None: not a keyword/tier).
    pub fn value_of<'m>(&self, m: &'m Material, subject: &str) -> Option<&'m str> {
        if subject == "tier" {
            return Some(&m.tiers.values[self.tier]);
        }
        self.keywords
            .iter()
            .find(|(k, _)| m.keywords[*k].name == subject)
            .map(|&(k, v)| m.keywords[k].values[v].as_str())
    }

    pub fn matches(&self, m: &Material, conds: &[Condition]) -> bool {
        conds
            .iter()
            .all(|c| crate::condition::holds(c, self.value_of(m, &c.subject)))
    }
}

/// Every variant before exclusion, tier outermost, then keywords in declaration order.
pub fn all_variants(m: &Material) -> Vec<VariantKey> {
    let statics: Vec<usize> = (0..m.keywords.len())
        .filter(|&k| m.keywords[k].mode == KeywordMode::Static)
        .collect();
    let mut out = Vec::new();
    for tier in 0..m.tiers.values.len() {
        let mut combos: Vec<Vec<(usize, usize)>> = vec![Vec::new()];
        for &k in &statics {
            let mut next = Vec::new();
            for c in &combos {
                for v in 0..m.keywords[k].values.len() {
                    let mut c2 = c.clone();
                    c2.push((k, v));
                    next.push(c2);
                }
            }
            combos = next;
        }
        out.extend(
            combos
                .into_iter()
                .map(|keywords| VariantKey { tier, keywords }),
        );
    }
    out
}

/// The variants the material compiles: all minus excluded.
pub fn variants(m: &Material) -> Vec<VariantKey> {
    all_variants(m)
        .into_iter()
        .filter(|v| !m.exclude.iter().any(|e| v.matches(m, e)))
        .collect()
}

/// The variant the inspector starts from: default tier and keyword values.
pub fn default_variant(m: &Material) -> VariantKey {
    VariantKey {
        tier: m.tiers.default,
        keywords: (0..m.keywords.len())
            .filter(|&k| m.keywords[k].mode == KeywordMode::Static)
            .map(|k| (k, m.keywords[k].default))
            .collect(),
    }
}
