//! Integration tests of dirac, compiled as one binary.
