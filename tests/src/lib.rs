//! Test-only helpers shared by the integration tests.
