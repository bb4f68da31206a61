# ringchain generated code v1 sha256=fe9466747b8e7acd76ebad2381d6dc9d885488c6454f3e833acec8359c75e66b
# derivation: plastic._restitution
# source key: f3be020559998432f519 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: v
# expression sha256: db8d380bfa7ec0888a8ef14315461b0b68357600a282bc36efca1325db3a8646 (of its srepr)
def _lambdifygenerated(v):
    x0 = numpy.sqrt(6/5 - (1/5)/v**2)
    return x0/((2/3)*v*x0 + 1/3)**(1/4)
