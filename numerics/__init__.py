"""Lattice models of chains of interlocked rings, checked against :mod:`ringchain.theory`."""
