/* SPDX-License-Identifier: Apache-2.0 */
/* The bytes of ISA-L's level buffer that its state takes before the compressor's token buffer
 * (what igzip.c's init_lvlX_buf returns). The state holds pointers, so it is smaller on a 32-bit
 * machine (WebAssembly): formats/src/imageio/PngWriter.cpp gives every build the token buffer of
 * the 64-bit build, so that its blocks end where they end there and the PNG bytes are the same. */
#include <stddef.h>

#include "igzip_level_buf_structs.h"

size_t lutkit_isal_level_state_bytes(int level) {
    const size_t head = sizeof(struct level_buf) - MAX_LVL_BUF_SIZE;
    if (level <= 1)
        return head + sizeof(struct hash8k_buf);
    if (level == 2)
        return head + sizeof(struct hash_hist_buf);
    return head + sizeof(struct hash_map_buf);
}
