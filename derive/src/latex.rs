//! LaTeX printer (todo)
