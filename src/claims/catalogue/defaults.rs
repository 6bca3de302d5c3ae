//! The defaults and allowed ranges of the optional numeric fields of a claim, in one
//! table ([`DEFAULTS`]) that the loader applies and `identities/README.md` quotes
//! ([`readme_table`]).  A value outside its range is a load error, never clamped.

/// An optional numeric field: its default and its allowed range.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FieldDefault {
    /// The field.
    pub field: &'static str,
    /// Which claims read it.
    pub applies: &'static str,
    /// The value when the field is absent.
    pub value: f64,
    /// Smallest allowed value.
    pub min: f64,
    /// Largest allowed value (`f64::INFINITY`: none).
    pub max: f64,
    /// What it sets.
    pub meaning: &'static str,
}

const INF: f64 = f64::INFINITY;

/// The defaults, in the order of the catalogue format.
pub const DEFAULTS: [FieldDefault; 10] = [
    FieldDefault {
        field: "samples",
        applies: "all but definitions",
        value: 8.0,
        min: 1.0,
        max: 10_000.0,
        meaning: "number of sample points",
    },
    FieldDefault {
        field: "max_loss_bits",
        applies: "all but definitions",
        value: 24.0,
        min: 0.0,
        max: INF,
        meaning: "bound g on bits lost to conditioning",
    },
    FieldDefault {
        field: "refute_floor_bits",
        applies: "all but definitions",
        value: 30.0,
        min: 0.0,
        max: INF,
        meaning: "refuted needs residuals ≥ 2^-this at every judged rung",
    },
    FieldDefault {
        field: "seed",
        applies: "all but definitions",
        value: 0.0,
        min: 0.0,
        max: INF,
        meaning: "random seed (combined with the claim id)",
    },
    FieldDefault {
        field: "exact_samples",
        applies: "identity with exact = true",
        value: 4.0,
        min: 1.0,
        max: 10_000.0,
        meaning: "rational points of the exact evaluation",
    },
    FieldDefault {
        field: "redraws",
        applies: "independence",
        value: 3.0,
        min: 1.0,
        max: 100.0,
        meaning: "redraws of the variable wrt per sample",
    },
    FieldDefault {
        field: "h0",
        applies: "asymptotic",
        value: 0.1,
        min: f64::MIN_POSITIVE,
        max: INF,
        meaning: "largest h",
    },
    FieldDefault {
        field: "steps",
        applies: "asymptotic",
        value: 6.0,
        min: 3.0,
        max: 60.0,
        meaning: "number of h values, h_j = h0·2^-j",
    },
    FieldDefault {
        field: "slope_tol",
        applies: "asymptotic",
        value: 0.1,
        min: 0.0,
        max: INF,
        meaning: "threshold order − slope_tol for the fitted and local slopes",
    },
    FieldDefault {
        field: "tries",
        applies: "existence",
        value: 4.0,
        min: 1.0,
        max: 100.0,
        meaning: "Newton starts per sample",
    },
];

/// The entry of `field`.
pub fn of(field: &str) -> &'static FieldDefault {
    DEFAULTS
        .iter()
        .find(|d| d.field == field)
        .unwrap_or(&DEFAULTS[0])
}

/// `field`'s value: `own` if given and in range, else the default.  The error names
/// the range.
pub fn pick(field: &str, own: Option<f64>) -> Result<f64, String> {
    let d = of(field);
    let v = own.unwrap_or(d.value);
    if v.is_finite() && v >= d.min && v <= d.max {
        Ok(v)
    } else if !v.is_finite() {
        Err(format!(
            "{field} must be a finite number {}, not {v}",
            range(d)
        ))
    } else {
        // a short form of very small or large values (1e-320, not 320 digits)
        let shown = if v != 0.0 && !(1e-6..1e15).contains(&v.abs()) {
            format!("{v:e}")
        } else {
            format!("{v}")
        };
        let sub = if v > 0.0 && v < f64::MIN_POSITIVE {
            " (below the smallest normal double, 2.2e-308)"
        } else {
            ""
        };
        Err(format!("{field} must be {}, not {shown}{sub}", range(d)))
    }
}

/// An integer field: [`pick`] as `usize`.
pub fn pick_count(field: &str, own: Option<usize>) -> Result<usize, String> {
    pick(field, own.map(|n| n as f64)).map(|v| v as usize)
}

fn range(d: &FieldDefault) -> String {
    match (d.min, d.max) {
        (lo, INF) if lo == f64::MIN_POSITIVE => "positive".into(),
        (lo, INF) => format!("at least {lo}"),
        (lo, hi) => format!("between {lo} and {hi}"),
    }
}

/// The defaults table of `identities/README.md`.
pub fn readme_table() -> String {
    let mut s = String::from("| field | for | default | allowed | sets |\n|---|---|---|---|---|\n");
    for d in &DEFAULTS {
        s.push_str(&format!(
            "| `{}` | {} | {} | {} | {} |\n",
            d.field,
            d.applies,
            d.value,
            range(d),
            d.meaning
        ));
    }
    s
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn defaults_apply_and_ranges_are_errors() {
        assert_eq!(pick_count("samples", None), Ok(8));
        assert_eq!(pick_count("samples", Some(20)), Ok(20));
        assert_eq!(
            pick_count("samples", Some(0)).unwrap_err(),
            "samples must be between 1 and 10000, not 0"
        );
        assert_eq!(
            pick("h0", Some(-1.0)).unwrap_err(),
            "h0 must be positive, not -1"
        );
        assert!(pick("slope_tol", Some(f64::NAN)).is_err());
        assert!(
            DEFAULTS
                .iter()
                .all(|d| d.value >= d.min && d.value <= d.max)
        );
    }

    #[test]
    fn the_readme_quotes_this_table() {
        let readme = include_str!("../../../identities/README.md");
        assert!(readme.contains(&readme_table()), "{}", readme_table());
    }
}
