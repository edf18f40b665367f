//! The Pareto plot of a material's tiers: cost against error, one point per
//! tier from the shading bench's timing, and per GPU-model family the same
//! tier at its modelled cost (same error, another marker). Hand-written SVG.

use std::fmt::Write as _;
use weft_meta::gpu_model::ModelSummary;
use weft_meta::{Measurements, TierMeasurement};

/// 1-2-5 ticks from the largest one at or below `min` to the smallest at or
/// above `max` (both > 0).
fn log_ticks(min: f64, max: f64) -> Vec<f64> {
    let mut ticks = Vec::new();
    let mut decade = 10f64.powf(min.log10().floor());
    'outer: loop {
        for m in [1.0, 2.0, 5.0] {
            let t = decade * m;
            if t * 2.5 < min && ticks.is_empty() {
                continue;
            }
            ticks.push(t);
            if t >= max {
                break 'outer;
            }
        }
        decade *= 10.0;
    }
    ticks
}

/// Stroke colours of the model families' markers.
const MODEL_COLOURS: [&str; 2] = ["#1864ab", "#2b8a3e"];

pub(crate) fn xml(s: &str) -> String {
    s.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
}

/// A round step for about `n` ticks over [0, max].
fn tick_step(max: f64, n: f64) -> f64 {
    let raw = max / n;
    let mag = 10f64.powf(raw.log10().floor());
    let f = raw / mag;
    mag * if f <= 1.0 {
        1.0
    } else if f <= 2.0 {
        2.0
    } else if f <= 2.5 {
        2.5
    } else if f <= 5.0 {
        5.0
    } else {
        10.0
    }
}

/// Indices of the Pareto-optimal points (no other point is at most as
/// costly and at most as wrong, and strictly better in one), by cost.
pub fn pareto_front(points: &[(f64, f64)]) -> Vec<usize> {
    let mut front: Vec<usize> = (0..points.len())
        .filter(|&i| {
            let (c, e) = points[i];
            !points
                .iter()
                .enumerate()
                .any(|(j, &(c2, e2))| j != i && c2 <= c && e2 <= e && (c2 < c || e2 < e))
        })
        .collect();
    front.sort_by(|&a, &b| points[a].0.total_cmp(&points[b].0));
    front
}

/// The Pareto plot of one material: cost (GPU time relative to standard
/// fast, or ms when there is no baseline) against error (FLIP mean), one
/// point per tier, the front drawn as a staircase; with a model and relative
/// costs, each family's modelled cost of every tier as a second marker at
/// the same error.
pub fn pareto_svg(m: &Measurements, model: Option<&ModelSummary>) -> String {
    let relative = m.tiers.iter().all(|t| t.ratio_to_standard_fast.is_some());
    let modelled = modelled_costs(m, model, relative);
    let points: Vec<(f64, f64)> = m
        .tiers
        .iter()
        .map(|t| (cost(t, relative), error(t)))
        .collect();
    let plot = Plot::new(&points, &modelled, relative);
    let mut s = String::new();
    plot.header(&mut s, m);
    plot.axes(&mut s, m, modelled.is_empty());
    let front = front(m, &points);
    plot.front(&mut s, &points, &front);
    plot.modelled(&mut s, m, &points, &modelled);
    plot.points(&mut s, m, &points, &front);
    plot.legend(&mut s, m, &modelled);
    s.push_str("</svg>\n");
    s
}

/// Per model family, each tier's modelled cost (× standard fast), when
/// costs are relative and there is a model.
fn modelled_costs<'a>(
    m: &Measurements,
    model: Option<&'a ModelSummary>,
    relative: bool,
) -> Vec<(&'a str, Vec<Option<f64>>)> {
    match model {
        Some(model) if relative => model
            .families
            .iter()
            .map(|f| {
                let per_tier = m
                    .tiers
                    .iter()
                    .map(|t| f.tier(&m.material, &t.tier).map(|c| c.executed_ratio))
                    .collect();
                (f.family.as_str(), per_tier)
            })
            .collect(),
        _ => Vec::new(),
    }
}

/// A tier's cost on the plot: × standard fast when `relative`, else ms.
fn cost(t: &TierMeasurement, relative: bool) -> f64 {
    if relative {
        t.ratio_to_standard_fast.unwrap_or(t.gpu_ms)
    } else {
        t.gpu_ms
    }
}

/// A tier's error on the plot: the worst cell of the error grid where it
/// was measured.
fn error(t: &TierMeasurement) -> f64 {
    t.flip_worst.unwrap_or(t.flip_mean)
}

fn is_look(t: &TierMeasurement) -> bool {
    t.kind.as_deref() == Some("look")
}

/// The front: the optimal points by cost; looks are not approximations and
/// take no part in it.
fn front(m: &Measurements, points: &[(f64, f64)]) -> Vec<usize> {
    let candidates: Vec<usize> = (0..points.len())
        .filter(|&i| !is_look(&m.tiers[i]))
        .collect();
    pareto_front(&candidates.iter().map(|&i| points[i]).collect::<Vec<_>>())
        .into_iter()
        .map(|k| candidates[k])
        .collect()
}

/// The plot's frame and axes: sizes, margins, the x axis (linear or log)
/// and the y axis, and where a value lands in pixels.
struct Plot {
    relative: bool,
    /// Height of the second legend line (the model's markers), 0 without.
    extra: f64,
    w: f64,
    h: f64,
    left: f64,
    top: f64,
    pw: f64,
    ph: f64,
    log_x: bool,
    max_x: f64,
    max_y: f64,
    sy: f64,
    x_ticks: Vec<f64>,
    /// The x axis' ends (log10 of the end ticks on a log axis).
    lo: f64,
    hi: f64,
}

impl Plot {
    fn new(points: &[(f64, f64)], modelled: &[(&str, Vec<Option<f64>>)], relative: bool) -> Plot {
        // A second legend line for the model's markers.
        let extra = if modelled.is_empty() { 0.0 } else { 16.0 };
        let (w, h) = (640.0, 420.0 + extra);
        let (left, right, top, bottom) = (78.0, 40.0, 84.0 + extra, 58.0);
        let (pw, ph) = (w - left - right, h - top - bottom);
        let all_x: Vec<f64> = points
            .iter()
            .map(|p| p.0)
            .chain(
                modelled
                    .iter()
                    .flat_map(|(_, v)| v.iter().flatten().copied()),
            )
            .collect();
        let max_x = all_x.iter().copied().fold(0.0, f64::max).max(1e-9) * 1.15;
        let min_x = all_x
            .iter()
            .copied()
            .filter(|x| *x > 0.0)
            .fold(f64::INFINITY, f64::min);
        // Relative costs spanning more than 20× (a model's loop-heavy reference
        // beside its approximations) are drawn on a log axis: 1-2-5 ticks.
        let log_x = relative && min_x.is_finite() && max_x / min_x > 20.0;
        let max_y = points.iter().map(|p| p.1).fold(0.0, f64::max).max(1e-4) * 1.2;
        let (sx, sy) = (tick_step(max_x, 5.0), tick_step(max_y, 5.0));
        let (max_x, max_y) = ((max_x / sx).ceil() * sx, (max_y / sy).ceil() * sy);
        let x_ticks: Vec<f64> = if log_x {
            log_ticks(min_x / 1.3, max_x)
        } else {
            (0..)
                .map(|k| k as f64 * sx)
                .take_while(|x| *x <= max_x + sx * 1e-6)
                .collect()
        };
        let (lo, hi) = if log_x {
            (x_ticks[0].log10(), x_ticks[x_ticks.len() - 1].log10())
        } else {
            (0.0, max_x)
        };
        Plot {
            relative,
            extra,
            w,
            h,
            left,
            top,
            pw,
            ph,
            log_x,
            max_x,
            max_y,
            sy,
            x_ticks,
            lo,
            hi,
        }
    }

    fn px(&self, x: f64) -> f64 {
        if self.log_x {
            self.left + (x.max(1e-9).log10() - self.lo) / (self.hi - self.lo) * self.pw
        } else {
            self.left + x / self.max_x * self.pw
        }
    }

    fn py(&self, y: f64) -> f64 {
        self.top + self.ph - y / self.max_y * self.ph
    }

    /// The opening tag, the background and the title lines.
    fn header(&self, s: &mut String, m: &Measurements) {
        let (w, h, left) = (self.w, self.h, self.left);
        let _ = writeln!(
            s,
            r#"<svg xmlns="http://www.w3.org/2000/svg" width="{w}" height="{h}" viewBox="0 0 {w} {h}" font-family="sans-serif" font-size="12">"#
        );
        let _ = writeln!(s, r#"<rect width="{w}" height="{h}" fill="white"/>"#);
        let _ = writeln!(
            s,
            r#"<text x="{}" y="22" font-size="15" font-weight="bold">{}: cost vs error per tier</text>"#,
            left,
            xml(&m.material)
        );
        let _ = writeln!(
            s,
            r##"<text x="{}" y="38" font-size="10" fill="#555">{}x{} {}, median frame time ({}); error against the reference tier over object pixels</text><text x="{}" y="51" font-size="10" fill="#555">on {}</text>"##,
            left,
            m.width,
            m.height,
            xml(&m.scene),
            xml(&m.timer),
            left,
            xml(&m.adapter),
        );
    }

    /// Grid lines, ticks, the axes and their labels.
    fn axes(&self, s: &mut String, m: &Measurements, unmodelled: bool) {
        let (left, top, pw, ph) = (self.left, self.top, self.pw, self.ph);
        for &x in &self.x_ticks {
            let gx = self.px(x);
            let _ = writeln!(
                s,
                r##"<line x1="{gx:.1}" y1="{top}" x2="{gx:.1}" y2="{:.1}" stroke="#e4e4e4"/><text x="{gx:.1}" y="{:.1}" text-anchor="middle">{}</text>"##,
                top + ph,
                top + ph + 16.0,
                trim(x)
            );
        }
        let mut y = 0.0;
        while y <= self.max_y + self.sy * 1e-6 {
            let gy = self.py(y);
            let _ = writeln!(
                s,
                r##"<line x1="{left}" y1="{gy:.1}" x2="{:.1}" y2="{gy:.1}" stroke="#e4e4e4"/><text x="{:.1}" y="{:.1}" text-anchor="end">{}</text>"##,
                left + pw,
                left - 6.0,
                gy + 4.0,
                trim(y)
            );
            y += self.sy;
        }
        let _ = writeln!(
            s,
            r#"<path d="M{left},{top} V{:.1} H{:.1}" fill="none" stroke="black"/>"#,
            top + ph,
            left + pw
        );
        let xlabel = match (self.relative, unmodelled) {
            (true, true) => "GPU time per frame (× standard fast)",
            (true, false) if self.log_x => {
                "cost × standard fast, log scale: timed (circles), GPU model (diamonds, triangles)"
            }
            (true, false) => {
                "cost × standard fast: timed (circles), GPU model (diamonds, triangles)"
            }
            _ => "GPU time per frame (ms)",
        };
        let _ = writeln!(
            s,
            r#"<text x="{:.1}" y="{:.1}" text-anchor="middle">{xlabel}</text>"#,
            left + pw / 2.0,
            self.h - 14.0
        );
        let grid = m.tiers.iter().any(|t| t.flip_worst.is_some());
        let ylabel = if grid {
            "error: worst FLIP mean over presets × scenes × lights"
        } else {
            "error: FLIP mean vs reference tier"
        };
        let _ = writeln!(
            s,
            r#"<text transform="translate(20 {:.1}) rotate(-90)" text-anchor="middle">{ylabel}</text>"#,
            top + ph / 2.0
        );
    }

    /// The front as a staircase through its points.
    fn front(&self, s: &mut String, points: &[(f64, f64)], front: &[usize]) {
        if front.is_empty() {
            return;
        }
        let mut d = String::new();
        for (k, &i) in front.iter().enumerate() {
            let (cx, cy) = (self.px(points[i].0), self.py(points[i].1));
            if k == 0 {
                let _ = write!(d, "M{cx:.1},{:.1} V{cy:.1}", self.top);
            } else {
                let _ = write!(d, " H{cx:.1} V{cy:.1}");
            }
        }
        let _ = write!(d, " H{:.1}", self.left + self.pw);
        let _ = writeln!(
            s,
            r##"<path d="{d}" fill="none" stroke="#d9480f" stroke-width="1.5" stroke-dasharray="5 3"/>"##
        );
    }

    /// Modelled costs: a diamond (first family) or a triangle (second) per
    /// tier at the tier's error, joined to its timed point by a faint line.
    fn modelled(
        &self,
        s: &mut String,
        m: &Measurements,
        points: &[(f64, f64)],
        modelled: &[(&str, Vec<Option<f64>>)],
    ) {
        for (k, (family, per_tier)) in modelled.iter().enumerate() {
            let colour = MODEL_COLOURS[k % MODEL_COLOURS.len()];
            for (i, t) in m.tiers.iter().enumerate() {
                let Some(x) = per_tier[i] else { continue };
                let (cx, cy) = (self.px(x), self.py(points[i].1));
                let _ = writeln!(
                    s,
                    r#"<line x1="{:.1}" y1="{cy:.1}" x2="{cx:.1}" y2="{cy:.1}" stroke="{colour}" stroke-opacity="0.35"/>"#,
                    self.px(points[i].0)
                );
                let title = format!("{}: {family} model {x:.2}× standard fast", xml(&t.tier));
                let shape = if k == 0 {
                    format!(
                        "M{cx:.1},{:.1} L{:.1},{cy:.1} L{cx:.1},{:.1} L{:.1},{cy:.1} Z",
                        cy - 5.0,
                        cx + 5.0,
                        cy + 5.0,
                        cx - 5.0
                    )
                } else {
                    format!(
                        "M{cx:.1},{:.1} L{:.1},{:.1} L{:.1},{:.1} Z",
                        cy - 5.0,
                        cx + 5.0,
                        cy + 4.0,
                        cx - 5.0,
                        cy + 4.0
                    )
                };
                let _ = writeln!(
                    s,
                    r#"<path d="{shape}" fill="white" stroke="{colour}" stroke-width="1.5"><title>{title}</title></path>"#
                );
            }
        }
    }

    /// Each tier's timed point (a square for a look) and its label.
    fn points(&self, s: &mut String, m: &Measurements, points: &[(f64, f64)], front: &[usize]) {
        for (i, t) in m.tiers.iter().enumerate() {
            let (cx, cy) = (self.px(points[i].0), self.py(points[i].1));
            let title = format!(
                "{}{}: {:.3} ms, FLIP {:.4} at the defaults, worst {:.4}, RMSE {:.4}, {} SPIR-V instructions",
                xml(&t.tier),
                if is_look(t) { " (look)" } else { "" },
                t.gpu_ms,
                t.flip_mean,
                error(t),
                t.rel_rmse,
                t.spirv_instructions
            );
            if is_look(t) {
                let _ = writeln!(
                    s,
                    r##"<rect x="{:.1}" y="{:.1}" width="10" height="10" fill="#adb5bd" stroke="#495057"><title>{title}</title></rect>"##,
                    cx - 5.0,
                    cy - 5.0
                );
            } else {
                let fill = if front.contains(&i) {
                    "#d9480f"
                } else {
                    "white"
                };
                let _ = writeln!(
                    s,
                    r##"<circle cx="{cx:.1}" cy="{cy:.1}" r="5" fill="{fill}" stroke="#d9480f" stroke-width="1.5"><title>{title}</title></circle>"##
                );
            }
            // Labels of points in the right half go to their left.
            let (lx, anchor) = if cx > self.left + self.pw * 0.55 {
                (cx - 8.0, "end")
            } else {
                (cx + 8.0, "start")
            };
            let _ = writeln!(
                s,
                r#"<text x="{lx:.1}" y="{:.1}" text-anchor="{anchor}">{}{} ({:.2} ms, FLIP {:.3})</text>"#,
                cy - 7.0,
                xml(&t.tier),
                if is_look(t) { " — look" } else { "" },
                t.gpu_ms,
                error(t)
            );
        }
    }

    /// The legend above the plot and the `standard fast` line.
    fn legend(&self, s: &mut String, m: &Measurements, modelled: &[(&str, Vec<Option<f64>>)]) {
        let (lx, ly) = (self.left + 10.0, self.top - 18.0 - self.extra);
        let _ = writeln!(
            s,
            r##"<circle cx="{lx}" cy="{ly}" r="5" fill="#d9480f"/><text x="{}" y="{}">on the Pareto front</text>"##,
            lx + 10.0,
            ly + 4.0
        );
        let _ = writeln!(
            s,
            r##"<circle cx="{}" cy="{ly}" r="5" fill="white" stroke="#d9480f" stroke-width="1.5"/><text x="{}" y="{}">dominated</text>"##,
            lx + 150.0,
            lx + 160.0,
            ly + 4.0
        );
        for (k, (family, _)) in modelled.iter().enumerate() {
            let colour = MODEL_COLOURS[k % MODEL_COLOURS.len()];
            let _ = writeln!(
                s,
                r#"<text x="{:.1}" y="{}" fill="{colour}">{} {family} model (executed cost)</text>"#,
                lx + 200.0 * k as f64,
                ly + 20.0,
                if k == 0 { "◇" } else { "△" }
            );
        }
        if m.tiers.iter().any(is_look) {
            let _ = writeln!(
                s,
                r##"<rect x="{}" y="{}" width="10" height="10" fill="#adb5bd" stroke="#495057"/><text x="{}" y="{}">look: a different model, not an approximation</text>"##,
                lx + 245.0,
                ly - 5.0,
                lx + 260.0,
                ly + 4.0
            );
        }
        let top = self.top;
        if self.relative && 1.0 <= self.max_x && (!self.log_x || self.x_ticks[0] <= 1.0) {
            let _ = writeln!(
                s,
                r##"<line x1="{x:.1}" y1="{top}" x2="{x:.1}" y2="{:.1}" stroke="#1971c2" stroke-dasharray="2 3"/><text x="{:.1}" y="{:.1}" fill="#1971c2" font-size="10">standard fast</text>"##,
                top + self.ph,
                self.px(1.0) + 4.0,
                top + 12.0,
                x = self.px(1.0)
            );
        }
    }
}

fn trim(v: f64) -> String {
    let s = format!("{v:.4}");
    let s = s.trim_end_matches('0').trim_end_matches('.');
    if s.is_empty() || s == "-0" {
        "0".into()
    } else {
        s.into()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn log_ticks_cover_the_range_in_1_2_5_steps() {
        assert_eq!(
            log_ticks(0.8, 240.0),
            [0.5, 1.0, 2.0, 5.0, 10.0, 20.0, 50.0, 100.0, 200.0, 500.0]
        );
        assert_eq!(log_ticks(1.0, 3.0), [1.0, 2.0, 5.0]);
    }

    #[test]
    fn pareto_front_drops_dominated_points() {
        let pts = [(1.0, 0.1), (2.0, 0.0), (3.0, 0.05), (1.0, 0.2)];
        assert_eq!(pareto_front(&pts), vec![0, 1]);
    }
}
