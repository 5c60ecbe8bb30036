"""Figure scripts of the paper, one module per figure.

Every module has ``compute(...)``, which returns a small frozen dataclass with the numbers of
the figure, and ``plot(data, path)``, which draws them (matplotlib is imported only there).
"""
