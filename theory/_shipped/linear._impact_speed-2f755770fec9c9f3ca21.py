# ringchain generated code v1 sha256=c71b893e44b16bd50997e4e4f859623356ef9183c0decbcb27cee952c5099731
# derivation: linear._impact_speed
# source key: 0d3b9b67499038ff2889 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: h, g
# expression sha256: 78e19f22b1980e24ec3dd4fe4cae41965662f526eed175e5eee688ad141fb7c8 (of its srepr)
def _lambdifygenerated(h, g):
    return numpy.sqrt(2)*numpy.sqrt(g)*numpy.sqrt(h)
