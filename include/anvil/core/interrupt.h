// Ctrl-C (SIGINT), SIGTERM, and SIGUSR1 (Ctrl-C as anvil run passes it on
// through mpirun, which would otherwise kill the processes 1 s after its
// SIGTERM) during a run: the first asks the run to stop at its next safe
// point (a Krylov or Newton iteration, an increment), where it checkpoints
// the last accepted increment and says how to resume; a second one ends the
// process at once.
#pragma once

namespace anvil::interrupt {

/// Installs the handlers for SIGINT, SIGTERM and SIGUSR1 (once per process).
void install();

/// The signal that asked this process to stop, 0 when none did.
int received();

/// The signal any process of the run received (0 when none), the same on
/// every process: a collective call, made by all processes at the same point.
int requested();

/// "SIGINT", "SIGTERM".
const char* name(int signal);

} // namespace anvil::interrupt
