# ringchain generated code v1 sha256=2d12a09b81cb9ebf048811fd3c4ec20082c7c654d7518b0a053cd9ac7d6be924
# derivation: contact._minimum_angle_pair
# source key: 67895ff0807168ca9dd5 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: R_1, r_1, R_2, r_2
# expression sha256: 2395f2c0189329a23d57f0db5ed475415e7ad6c0338c8239b1f6d48740869674 (of its srepr)
def _lambdifygenerated(R_1, r_1, R_2, r_2):
    return numpy.arcsin(numpy.sqrt(r_1 + r_2)*numpy.sqrt(R_1 + R_2 - r_1 - r_2)/(numpy.sqrt(R_1)*numpy.sqrt(R_2)))
