"""Solvers without time integration: quasi-static load distribution, steady and quasi-dynamic
rolling states, the start state of a run, raceway control, shaft equilibrium, Newton's method."""
