"""Accuracy harness: generated quantities against independent 50-digit mpmath references."""
