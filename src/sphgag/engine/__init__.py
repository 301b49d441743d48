"""The discrete model: particle layout, kernel, TLSPH forces and Jacobian, loads, particle history, and the quasi-
static solvers that reach converged states (paper sections 2.1-2.4).
"""
