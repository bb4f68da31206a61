# ringchain generated code v1 sha256=e7e6b6b484c5c58cc3418a6ce1b8ab17c9bfe0b5d1831c3a5b1d2051a1cc8a85
# derivation: contact._minimum_angle_pair
# source key: ceca10620e89af986038 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: R_1, r_1, R_2, r_2
# expression sha256: 2395f2c0189329a23d57f0db5ed475415e7ad6c0338c8239b1f6d48740869674 (of its srepr)
def _lambdifygenerated(R_1, r_1, R_2, r_2):
    return numpy.arcsin(numpy.sqrt(r_1 + r_2)*numpy.sqrt(R_1 + R_2 - r_1 - r_2)/(numpy.sqrt(R_1)*numpy.sqrt(R_2)))
