# ringchain generated code v1 sha256=5f997481c5c0c649b383475f95eabadc68d002d159731436f84492a397975c22
# derivation: rigid._modulus_pair
# source key: aaa6be78b00d30412b2b (theory/*.py, sympy 1.14.0, numpy 2.4.6)
# arguments: E_1, nu_1, E_2, nu_2
# expression sha256: 048c9cabb01bda9f3cab2a722b38eb0c89f51ffe1d090e7feeb1e997fdf02c9a (of its srepr)
def _lambdifygenerated(E_1, nu_1, E_2, nu_2):
    return -E_1*E_2/(E_1*nu_2**2 - E_1 + E_2*nu_1**2 - E_2)
