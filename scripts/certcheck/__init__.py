"""The recheck of eulertop certificates: the claim's binding to the catalogue (binding),
the expression language (exprlang) and its evaluation from a certificate's symbols
(evaluate, formula).  The derivation itself is rechecked by recheck-certificates.py."""
