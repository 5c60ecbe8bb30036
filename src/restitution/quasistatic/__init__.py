"""Layer 3, quasistatic theory: Hertz-type contact, relaxation, Rayleigh's estimate (section 5)."""
