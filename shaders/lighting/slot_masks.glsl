// The clusters' light masks and summaries (clusters.glsl), split over two storage buffers so that together they
// may exceed the driver's largest storage block (128 MiB on llvmpipe): slots below slotsPerBuffer() in the first,
// the others in the second, each buffer holding its slots' masks, then their summaries. Include after
// clusters.glsl, with SLOT_MASKS_QUALIFIER defined (readonly, writeonly or empty).
layout(std430, binding = SLOT_MASKS_SSBO) SLOT_MASKS_QUALIFIER buffer SlotMasksLow { uint masksLow[]; };
layout(std430, binding = SLOT_MASKS_HIGH_SSBO) SLOT_MASKS_QUALIFIER buffer SlotMasksHigh { uint masksHigh[]; };

uint slotsPerBuffer() { return (slotCapacity() + 1u) / 2u; }
bool slotIsHigh(uint slot) { return slot >= slotsPerBuffer(); }
uint slotInBuffer(uint slot) { return slotIsHigh(slot) ? slot - slotsPerBuffer() : slot; }
// Word indices within the slot's buffer.
uint slotMaskBase(uint slot) { return slotInBuffer(slot) * slotMaskWords(); }
uint slotSummaryBase(uint slot) { return slotsPerBuffer() * slotMaskWords() + slotInBuffer(slot) * slotSummaryWords(); }
