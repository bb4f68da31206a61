# ringchain generated code v1 sha256=478f184902890f3da2aa4580df068408d5b2c1bace55638b96dae884653d2f9e
# derivation: rigid._modulus_pair
# source key: 67895ff0807168ca9dd5 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: E_1, nu_1, E_2, nu_2
# expression sha256: 048c9cabb01bda9f3cab2a722b38eb0c89f51ffe1d090e7feeb1e997fdf02c9a (of its srepr)
def _lambdifygenerated(E_1, nu_1, E_2, nu_2):
    return -E_1*E_2/(E_1*nu_2**2 - E_1 + E_2*nu_1**2 - E_2)
