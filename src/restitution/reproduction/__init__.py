"""Layer 6, the paper reproduced: figures, Table 1, the claims and their verdicts, the report."""
