# ringchain generated code v1 sha256=98d59a69d3526b6bfef012616116598db3aa838e46d722ad6f5b9e817455867a
# derivation: plastic._restitution
# source key: 317867d47b5755454417 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: v
# expression sha256: db8d380bfa7ec0888a8ef14315461b0b68357600a282bc36efca1325db3a8646 (of its srepr)
def _lambdifygenerated(v):
    x0 = numpy.sqrt(6/5 - (1/5)/v**2)
    return x0/((2/3)*v*x0 + 1/3)**(1/4)
