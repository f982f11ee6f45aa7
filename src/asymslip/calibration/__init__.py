"""Calibration of contact edges from pressure data."""
