//! `walker`: simulate any model file's walker (the paper's walkers are built in), sweep its
//! parameters, find and follow its limit cycles, reproduce the paper's figures, and draw the
//! gallery of the shipped walkers on a slippery floor. The command line is the library's
//! ([`walker_cli::main`]); a crate with walkers of its own calls [`walker_cli::main_with`].

fn main() -> std::process::ExitCode {
    walker_cli::main()
}
