"""The elastic disk of the paper (section 2): frequency equation, eigenmodes, surface quadrature."""
