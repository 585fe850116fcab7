// SPDX-License-Identifier: MIT
#version 460
// Writes its specialization constant to the buffer: which pipeline ran shows in what it wrote.
layout(local_size_x = 1) in;
layout(constant_id = 0) const uint value = 0;
layout(set = 0, binding = 0) writeonly buffer Out { uint written; };

void main() { written = value; }
