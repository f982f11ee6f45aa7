"""The generated C, Fortran and MATLAB/Octave code, compiled or run and compared with NumPy."""
