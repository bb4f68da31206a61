# ringchain generated code v1 sha256=e31e1ea8cc2dce54612b31dd4a51e6de99e55532e3b0f9458f9302dcafa6760b
# derivation: rigid._modulus_pair
# source key: ceca10620e89af986038 (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: E_1, nu_1, E_2, nu_2
# expression sha256: 048c9cabb01bda9f3cab2a722b38eb0c89f51ffe1d090e7feeb1e997fdf02c9a (of its srepr)
def _lambdifygenerated(E_1, nu_1, E_2, nu_2):
    return -E_1*E_2/(E_1*nu_2**2 - E_1 + E_2*nu_1**2 - E_2)
