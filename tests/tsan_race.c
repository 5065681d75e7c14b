/* SPDX-License-Identifier: MIT */
/* A planted data race: two threads add to one plain counter. Built only
 * under TSan (tests/tsan_check.sh runs it), where it must be reported and
 * fail (exit 66): the proof that a TSan report fails a test, so the whole
 * suite passing under TSan is not a check that cannot fail. */
#include <pthread.h>
#include <stdio.h>

static long counter;   /* no lock, no atomic: the race */

static void *add(void *arg)
{
    (void)arg;
    for (int k = 0; k < 100000; k++)
        counter++;
    return NULL;
}

int main(void)
{
    pthread_t a, b;
    if (pthread_create(&a, NULL, add, NULL) != 0 || pthread_create(&b, NULL, add, NULL) != 0)
        return 2;
    pthread_join(a, NULL);
    pthread_join(b, NULL);
    printf("counter %ld\n", counter);
    return 0;
}
