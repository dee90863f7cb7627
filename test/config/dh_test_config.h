/* SPDX-License-Identifier: Apache-2.0 */
/* Config header used by the "confighdr" variant of tools/check_variants.sh:
 * proves DH_CONFIG_HEADER is honoured (test_config checks the values). */
#ifndef DH_TEST_CONFIG_H
#define DH_TEST_CONFIG_H
#define DH_TEST_CONFIG_HEADER_SEEN 1
#endif
