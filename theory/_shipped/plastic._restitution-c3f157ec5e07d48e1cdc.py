# ringchain generated code v1 sha256=97713a5e672f02cd179bbbe82046d4e4c775e28f695e80c418665353ccd123c4
# derivation: plastic._restitution
# source key: caeff341571871d5b69b (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: v
# expression sha256: db8d380bfa7ec0888a8ef14315461b0b68357600a282bc36efca1325db3a8646 (of its srepr)
def _lambdifygenerated(v):
    x0 = numpy.sqrt(6/5 - (1/5)/v**2)
    return x0/((2/3)*v*x0 + 1/3)**(1/4)
