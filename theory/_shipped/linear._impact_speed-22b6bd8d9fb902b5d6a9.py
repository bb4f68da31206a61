# ringchain generated code v1 sha256=cbf65b4cca8f7757157ed827b7ccbe831bfc8760d01769c57244c1c1b35e5ee0
# derivation: linear._impact_speed
# source key: 0881d513a06819d2e367 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: h, g
# expression sha256: 78e19f22b1980e24ec3dd4fe4cae41965662f526eed175e5eee688ad141fb7c8 (of its srepr)
def _lambdifygenerated(h, g):
    return numpy.sqrt(2)*numpy.sqrt(g)*numpy.sqrt(h)
