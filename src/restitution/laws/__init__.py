"""Layer 5, laws: serving epsilon(v) from stored points, SI units, interpolation in nu, exports."""
