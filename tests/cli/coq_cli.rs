//! Command-line tests of `eulertop prove ID --coq FILE`: the Coq script of a proof
//! (compiled by coqc only in `scripts/check-coq.sh`, never here), and its refusals.

use std::process::Command;

fn run(args: &[&str]) -> (i32, String, String) {
    let o = Command::new(env!("CARGO_BIN_EXE_eulertop"))
        .args(args)
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .expect("eulertop runs");
    (
        o.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&o.stdout).into_owned(),
        String::from_utf8_lossy(&o.stderr).into_owned(),
    )
}

fn temp(name: &str) -> std::path::PathBuf {
    std::env::temp_dir().join(format!("eulertop-coq-{}-{name}", std::process::id()))
}

#[test]
fn a_proved_claim_gets_a_coq_script_stating_it() {
    let path = temp("sn-cn.v");
    let p = path.to_str().unwrap();
    let (code, out, err) = run(&["prove", "bg.dlmf-22.6.1.sn-cn", "--coq", p]);
    assert_eq!(code, 0, "{err}");
    assert!(out.contains("proved"), "{out}");
    let coq = std::fs::read_to_string(&path).expect("script written");
    let _ = std::fs::remove_file(&path);
    // the claim sn² + cn² − 1 = 0: its nodes, the relation cn² = 1 − sn², the theorem
    assert!(coq.contains("Variables k u v sn_1 cn_1 dn_1 : R."), "{coq}");
    assert!(
        coq.contains("Hypothesis rel_cn_1 : cn_1 ^ 2 = (- sn_1 ^ 2 + 1)."),
        "{coq}"
    );
    assert!(coq.contains("Definition t_10 := t_5 + t_9."), "{coq}");
    assert!(
        coq.contains("Theorem claim_holds : t_12 - t_13 = 0."),
        "{coq}"
    );
    assert!(coq.contains("Print Assumptions claim_holds."), "{coq}");
    assert!(
        coq.contains("(* source claim.lhs ''sn(u, k)^2 + cn(u, k)^2'' *)"),
        "{coq}"
    );
    for word in ["Admitted", "admit", "Axiom", "Parameter"] {
        assert!(!coq.contains(word), "{word} in\n{coq}");
    }
    // every lemma is closed
    assert_eq!(coq.matches("Proof.").count(), coq.matches("Qed.").count());
}

#[test]
fn an_addition_theorem_instance_is_a_named_hypothesis() {
    let path = temp("add-sn.v");
    let p = path.to_str().unwrap();
    let (code, _, err) = run(&["prove", "bg.dlmf-22.8.1.sn-addition", "--coq", p]);
    assert_eq!(code, 0, "{err}");
    let coq = std::fs::read_to_string(&path).expect("script written");
    let _ = std::fs::remove_file(&path);
    assert!(coq.contains("Variable ell_4 : R."), "{coq}");
    assert!(coq.contains("Hypothesis inst_4 : ell_4 = "), "{coq}");
    assert!(
        coq.contains("Hypothesis nz_4 : (k ^ 2 * sn_1 ^ 2 * sn_2 ^ 2 - 1) <> 0."),
        "{coq}"
    );
    assert!(coq.contains("Hypothesis dz_30 : t_29 <> 0."), "{coq}");
}

#[test]
fn no_script_for_a_claim_without_a_certificate_and_an_older_one_is_removed() {
    let path = temp("period.v");
    std::fs::write(&path, "stale").unwrap();
    let p = path.to_str().unwrap();
    // a shift by a third of K, which the certificate format does not record
    let (code, _, err) = run(&[
        "prove",
        "dlmf.22.9.13.s3",
        "--catalogue",
        "examples/dlmf-jacobi",
        "--coq",
        p,
    ]);
    assert_eq!(code, 2, "{err}");
    assert_eq!(err.lines().count(), 1, "{err}");
    assert!(err.contains("no Coq script written"), "{err}");
    assert!(err.contains("was removed"), "{err}");
    assert!(!path.exists(), "a stale script was left");
}

#[test]
fn lemma_2_has_a_script_with_its_branch_as_a_hypothesis() {
    let path = temp("lemma2.v");
    let p = path.to_str().unwrap();
    let (code, _, err) = run(&["prove", "sec8.lemma2.model", "--coq", p]);
    assert_eq!(code, 0, "{err}");
    let coq = std::fs::read_to_string(&path).expect("script written");
    let _ = std::fs::remove_file(&path);
    assert!(coq.contains("Hypothesis br_"), "{coq}");
    assert!(coq.contains("hypothesis.omega-near-identity"), "{coq}");
}

#[test]
fn a_derivative_is_refused_with_one_line() {
    let path = temp("dsn.v");
    let p = path.to_str().unwrap();
    let (code, _, err) = run(&["prove", "bg.dlmf-22.13.1.dsn", "--coq", p]);
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("derivative"), "{err}");
    assert!(!path.exists());
}

#[test]
fn an_unwritable_coq_path_fails_before_the_proof() {
    let (code, out, err) = run(&["prove", "bg.dlmf-22.6.1.sn-cn", "--coq", "/no/such/dir/x.v"]);
    assert_eq!(code, 2, "{err}");
    assert!(out.is_empty(), "{out}");
    assert!(
        err.contains("--coq '/no/such/dir/x.v': no directory"),
        "{err}"
    );
    let (code, _, err) = run(&["prove", "Lemma 2", "--coq", "x.v"]);
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("--coq needs one claim"), "{err}");
}

#[test]
fn the_steps_combine_fractions_by_lemmas_and_reduce_by_ring_with_the_relations() {
    let path = temp("ws.v");
    let p = path.to_str().unwrap();
    let (code, _, err) = run(&["prove", "sec5.ws.w1-w3", "--coq", p]);
    assert_eq!(code, 0, "{err}");
    let coq = std::fs::read_to_string(&path).expect("script written");
    let _ = std::fs::remove_file(&path);
    // the preamble's lemmas on atoms, and the tactic that applies them
    assert!(
        coq.contains("Lemma eu_addq a b c d : b <> 0 -> d <> 0 ->"),
        "{coq}"
    );
    assert!(
        coq.contains("Ltac eu_comb := repeat match goal with"),
        "{coq}"
    );
    let (_, body) = coq
        .split_once("\nModule Claim.")
        .expect("the claim's module");
    // a step on fractions: eu_comb, then the normal form by ring with the relations
    // it uses as rewriting rules; never field on the derivation's terms
    assert!(body.contains("  eu_comb.\n"), "{body}");
    assert!(body.contains("ring [rel_"), "{body}");
    assert!(
        body.contains("apply (eu_fracr _ _ _ _ (sn_1)); [nzp | ring | ]."),
        "{body}"
    );
    assert!(!body.contains("field"), "{body}");
    // a constant's or a symbol's node is its definition
    assert!(
        body.contains("Lemma e_4 : t_4 = (sn_1).\nProof.\n  unfold t_4.\n  reflexivity.\nQed."),
        "{body}"
    );
}
