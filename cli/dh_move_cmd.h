/* SPDX-License-Identifier: Apache-2.0 */
/*
 * dh_move_cmd.h - the `dhmath move` command (docs/cli.md, "move").
 */
#ifndef DHMATH_CLI_DH_MOVE_CMD_H
#define DHMATH_CLI_DH_MOVE_CMD_H

/** Usage lines of `move` for the help text. */
extern const char cli_move_usage[];

/** `dhmath move ROBOT --q0 Q --dt SECONDS SEGMENT... [options]` on the
 *  arguments after the command name: exit status 0 (every period ok),
 *  3 (lagging or unreachable periods, or the period cap reached) or 2
 *  (errors, nothing on stdout). */
int cli_cmd_move(int argc, char **argv);

#endif /* DHMATH_CLI_DH_MOVE_CMD_H */
