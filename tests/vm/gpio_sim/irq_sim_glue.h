/* SPDX-License-Identifier: GPL-2.0 */
/*
 * Glue that lets the kernel's kernel/irq/irq_sim.c (normally built in, CONFIG_IRQ_SIM) build as a module
 * for the VM test: force-included before it (tests/vm/gpio_sim/Kbuild). Two things differ for a module:
 * irq_to_desc() is no longer exported, so the same lookup goes through irq_get_irq_data(), which is; and
 * a module needs a licence to use the GPL-only irq_domain and irq_work symbols.
 */
#include <linux/irq.h>
#include <linux/irqdesc.h>
#include <linux/module.h>

static inline struct irq_desc* puddle_irq_to_desc(unsigned int irq) {
    struct irq_data* data = irq_get_irq_data(irq);

    return data ? irq_data_to_desc(data) : NULL;
}
/* irqdesc.h's declaration is already seen; from here on irq_sim.c's calls use the lookup above. */
#define irq_to_desc puddle_irq_to_desc

MODULE_LICENSE("GPL");
MODULE_DESCRIPTION("Interrupt simulator (kernel/irq/irq_sim.c as a module, for Puddle's VM test)");
