//! Proofs by parts of the domain: when a sign that the proof must decide differs
//! between domain points (the regime `E/M² ≷ 1/B` of a point of phase space, say), the
//! case is split by that sign, each part is drawn afresh and proved on its own, and the
//! claim is proved when every part is.  The parts cover the domain except where the
//! sign's value is 0.  At most [`MAX_SPLITS`] nested splits per case; a claim that
//! states a condition is not split (its signs must be proved, never assumed per part).

use super::case::{Region, Signs, prove_case};
use super::cases::{MAX_DRAWS, POINTS, Role, case_key};
use crate::algebra::split::SignSplit;
use crate::algebra::{BaseHint, Outcome, Proof};
use crate::claims::catalogue::PExpr;
use crate::claims::sampler::{Point, Stream};
use crate::claims::value::Value;
use crate::claims::verdict::context::Ctx;

/// The most nested splits of one case.
pub(super) const MAX_SPLITS: usize = 3;

/// The most indeterminates whose signs one proof carries as sign symbols.
pub(super) const MAX_FOLDS: usize = 3;

/// A part of the domain with its proof: the labels of its case and of its signs.
pub(super) type Part = (Vec<String>, Proof);

/// What a case's parts are proved from.
pub(super) struct CaseInput<'a, 'c> {
    pub ctx: Ctx<'c>,
    pub roles: &'a [(String, Role, &'c PExpr)],
    pub sides: (&'a PExpr, &'a PExpr),
    pub certificate: bool,
    pub signs: &'a Signs,
}

/// Proves one case, splitting it by signs that differ between its points; `Ok` with
/// every part when all are proved, else the first part that is not (boxed: a proof is
/// large).
pub(super) fn prove_parts(
    input: &CaseInput<'_, '_>,
    case: &[String],
    points: Vec<Point>,
    hints: Vec<BaseHint>,
) -> Result<Vec<Part>, Box<Part>> {
    parts(
        input,
        case,
        case.to_vec(),
        points,
        hints,
        &Region::default(),
    )
}

pub(super) fn parts(
    input: &CaseInput<'_, '_>,
    case: &[String],
    label: Vec<String>,
    points: Vec<Point>,
    hints: Vec<BaseHint>,
    region: &Region,
) -> Result<Vec<Part>, Box<Part>> {
    let ctx = input.ctx;
    let p = prove_case(
        ctx,
        input.roles,
        &points,
        input.sides,
        (input.certificate, input.signs),
        hints.clone(),
        region,
    );
    if p.is_proved() {
        return Ok(vec![(label, p)]);
    }
    let split = match &p.split {
        Some(s) if region.signs.len() < MAX_SPLITS => s.clone(),
        _ => return Err(Box::new((label, p))),
    };
    // the sign of an indeterminate first as a sign symbol: one proof for both signs
    if split.is_indeterminate()
        && region.folds.len() < MAX_FOLDS
        && !region.folds.iter().any(|f| f.same(&split))
    {
        let mut folded = region.clone();
        folded.folds.push(split.clone());
        let parts = parts(input, case, label.clone(), points, hints.clone(), &folded);
        if parts.is_ok() {
            return parts;
        }
    }
    let mut out = Vec::new();
    let mut empty = Vec::new();
    for sign in [1, -1] {
        if split.never(sign) {
            empty.push(format!(
                "the part where {} {} 0 is empty: the value is a sum of even powers with coefficients of one sign",
                split.what,
                if sign > 0 { ">" } else { "<" }
            ));
            continue;
        }
        let mut c = region.clone();
        c.signs.push((split.clone(), sign));
        let mut l = label.clone();
        l.push(format!(
            "{} {} 0",
            split.what,
            if sign > 0 { ">" } else { "<" }
        ));
        let pts = match draw(input, case, &c.signs) {
            Ok(pts) => pts,
            Err(why) => {
                let mut p = p;
                p.outcome = Outcome::NotProved(format!(
                    "the part where {} of the domain is not reached ({why}), so it is neither proved nor refuted",
                    l.join(", ")
                ));
                return Err(Box::new((l, p)));
            }
        };
        out.extend(parts(input, case, l, pts, hints.clone(), &c)?);
    }
    if let Some((_, first)) = out.first_mut() {
        first.notes.extend(empty);
    }
    Ok(out)
}

/// [`POINTS`] points of the case on which every sign condition holds: drawn as the
/// domain is sampled, else searched for next to the domain's boundary and vertices
/// ([`crate::claims::sampler::Sampler::toward_boundary`]).
pub(super) fn draw(
    input: &CaseInput<'_, '_>,
    case: &[String],
    conds: &[(SignSplit, i32)],
) -> Result<Vec<Point>, String> {
    draw_part(input.ctx, input.roles, case, conds)
}

/// [`draw`] for the claim `ctx` whose variables have the roles `roles`.
pub(super) fn draw_part(
    ctx: Ctx<'_>,
    roles: &[(String, Role, &PExpr)],
    case: &[String],
    conds: &[(SignSplit, i32)],
) -> Result<Vec<Point>, String> {
    let sampler = || ctx.sampler(Stream::Proof).map_err(|c| c.to_string());
    draw_with(roles, case, conds, sampler()?).or_else(|_| {
        draw_with(roles, case, conds, sampler()?.toward_boundary()).map_err(|_| {
            format!(
                "no {POINTS} points of it in {} draws of the domain, nor in {} draws next to its boundary",
                MAX_DRAWS * 4,
                MAX_DRAWS * 4
            )
        })
    })
}

/// [`draw_part`] with one sampler.
fn draw_with(
    roles: &[(String, Role, &PExpr)],
    case: &[String],
    conds: &[(SignSplit, i32)],
    mut sampler: crate::claims::sampler::Sampler<'_>,
) -> Result<Vec<Point>, String> {
    let case_vars: Vec<&String> = (roles.iter())
        .filter(|(_, r, _)| *r == Role::Case)
        .map(|(n, _, _)| n)
        .collect();
    let mut out = Vec::new();
    for _ in 0..MAX_DRAWS * 4 {
        let p = sampler.draw()?;
        if case_key(&p, &case_vars) != case {
            continue;
        }
        let on = |n: &str| value_of(&p, n);
        if conds.iter().all(|(c, s)| c.sign_at(&on) == Some(*s)) {
            out.push(p);
            if out.len() >= POINTS {
                return Ok(out);
            }
        }
    }
    Err("too few points on a part of the domain".into())
}

/// The value of an indeterminate at a point: a real variable, or a component `M2` of a
/// vector variable `M`.
pub(super) fn value_of(p: &Point, name: &str) -> Option<f64> {
    if let Some(Value::Real(x)) = p.get(name) {
        return Some(*x);
    }
    let (head, last) = name.split_at(name.len().checked_sub(1)?);
    let j: usize = last.parse().ok()?;
    match p.get(head) {
        Some(Value::Vec3(v)) if (1..=3).contains(&j) => Some(*v.get(j - 1)),
        _ => None,
    }
}
