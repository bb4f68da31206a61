# ringchain generated code v1 sha256=1df4da870f243c7496d3c770e4f938e22cf57ce4a8a87f97072236745e3ccf8a
# derivation: plastic._restitution
# source key: 67895ff0807168ca9dd5 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: v
# expression sha256: db8d380bfa7ec0888a8ef14315461b0b68357600a282bc36efca1325db3a8646 (of its srepr)
def _lambdifygenerated(v):
    x0 = numpy.sqrt(6/5 - (1/5)/v**2)
    return x0/((2/3)*v*x0 + 1/3)**(1/4)
