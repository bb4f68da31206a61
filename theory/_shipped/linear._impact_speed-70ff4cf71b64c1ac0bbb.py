# ringchain generated code v1 sha256=80c2943e04d87808e0a0cf00ef2c960709f9f4ba073b9bd9775e7a6a6b87b592
# derivation: linear._impact_speed
# source key: a22a0557fcec1bc1abe9 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: h, g
# expression sha256: 78e19f22b1980e24ec3dd4fe4cae41965662f526eed175e5eee688ad141fb7c8 (of its srepr)
def _lambdifygenerated(h, g):
    return numpy.sqrt(2)*numpy.sqrt(g)*numpy.sqrt(h)
