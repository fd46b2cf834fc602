"""Equilibria, their stability and normal modes; steady motions of the reduction."""
