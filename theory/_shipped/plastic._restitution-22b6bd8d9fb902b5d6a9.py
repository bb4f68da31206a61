# ringchain generated code v1 sha256=5580c2e0ad0a290c66644159bf5e1e0d48c3be53dd080dadd6193e349e8dfda5
# derivation: plastic._restitution
# source key: 0881d513a06819d2e367 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: v
# expression sha256: db8d380bfa7ec0888a8ef14315461b0b68357600a282bc36efca1325db3a8646 (of its srepr)
def _lambdifygenerated(v):
    x0 = numpy.sqrt(6/5 - (1/5)/v**2)
    return x0/((2/3)*v*x0 + 1/3)**(1/4)
