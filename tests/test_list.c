/* list.h: a growable array of void pointers with an optional element freer. */
#include <stdint.h>
#include <stdlib.h>
#include "jostle/list.h"
#include "test.h"

/* Counts the elements a freer was called on, and frees them. */
static int freed_count = 0;
static void counting_free(void *element) {
    freed_count++;
    free(element);
}

static int *new_int(int value) {
    int *p = malloc(sizeof *p);
    *p = value;
    return p;
}

static void init_is_empty(void) {
    list_t *list = list_init(10, NULL);
    CHECK(list != NULL);
    CHECK(list_size(list) == 0);
    list_free(list);
    list_t *no_room = list_init(0, free); /* capacity 0 is allowed */
    CHECK(list_size(no_room) == 0);
    list_free(no_room);
}

static void add_and_get_keep_order(void) {
    int values[5] = {10, 20, 30, 40, 50};
    list_t *list = list_init(5, NULL);
    for (int i = 0; i < 5; i++) list_add(list, &values[i]);
    CHECK(list_size(list) == 5);
    for (size_t i = 0; i < 5; i++) CHECK(list_get(list, i) == &values[i]);
    list_free(list); /* no freer: the stack values are not freed */
}

static void add_grows_past_initial_capacity(void) {
    /* Capacities 0 and 1 both have to grow many times; every element must
     * survive every move (AddressSanitizer catches writes past the end). */
    for (size_t capacity = 0; capacity <= 1; capacity++) {
        list_t *list = list_init(capacity, free);
        for (int i = 0; i < 1000; i++) list_add(list, new_int(i));
        CHECK(list_size(list) == 1000);
        bool all_there = true;
        for (size_t i = 0; i < 1000; i++) {
            all_there = all_there && *(int *)list_get(list, i) == (int)i;
        }
        CHECK(all_there);
        list_free(list);
    }
}

static void set_may_store_null(void) {
    /* list_add refuses NULL (below); list_set may blank a slot, and the
     * freer then meets the NULL (free(NULL) does nothing). */
    list_t *list = list_init(1, free);
    list_add(list, new_int(1));
    list_add(list, new_int(2));
    free(list_set(list, 1, NULL));
    CHECK(list_size(list) == 2);
    CHECK(list_get(list, 1) == NULL);
    list_free(list);
    CHECK(test_no_leaks());
}

static void remove_returns_element_and_shifts(void) {
    int values[5] = {0, 1, 2, 3, 4};
    list_t *list = list_init(2, NULL);
    for (int i = 0; i < 5; i++) list_add(list, &values[i]);
    CHECK(list_remove(list, 1) == &values[1]); /* middle */
    CHECK(list_size(list) == 4);
    CHECK(list_get(list, 0) == &values[0]);
    CHECK(list_get(list, 1) == &values[2]);
    CHECK(list_get(list, 2) == &values[3]);
    CHECK(list_get(list, 3) == &values[4]);
    CHECK(list_remove(list, 3) == &values[4]); /* last */
    CHECK(list_remove(list, 0) == &values[0]); /* first */
    CHECK(list_size(list) == 2);
    CHECK(list_get(list, 0) == &values[2]);
    CHECK(list_get(list, 1) == &values[3]);
    CHECK(list_remove(list, 0) == &values[2]);
    CHECK(list_remove(list, 0) == &values[3]);
    CHECK(list_size(list) == 0);
    list_add(list, &values[4]); /* usable again after emptying */
    CHECK(list_size(list) == 1 && list_get(list, 0) == &values[4]);
    list_free(list);
}

static void removed_element_belongs_to_caller(void) {
    freed_count = 0;
    list_t *list = list_init(3, counting_free);
    list_add(list, new_int(1));
    list_add(list, new_int(2));
    list_add(list, new_int(3));
    int *taken = list_remove(list, 1);
    CHECK(*taken == 2);
    list_free(list);
    CHECK(freed_count == 2); /* only the two still in the list */
    CHECK(*taken == 2);      /* still alive: AddressSanitizer would object */
    free(taken);
}

static void free_calls_freer_on_each_element(void) {
    freed_count = 0;
    list_t *list = list_init(0, counting_free);
    for (int i = 0; i < 7; i++) list_add(list, new_int(i));
    list_free(list);
    CHECK(freed_count == 7);
}

static void set_replaces_and_returns_old(void) {
    int a = 1, b = 2, c = 3;
    list_t *list = list_init(2, NULL);
    list_add(list, &a);
    list_add(list, &b);
    CHECK(list_set(list, 1, &c) == &b);
    CHECK(list_get(list, 1) == &c);
    CHECK(list_get(list, 0) == &a);
    CHECK(list_size(list) == 2);
    list_free(list);
}

/* Programmer errors: each aborts with a message naming the function. */
static list_t *three_element_list(void) {
    static int values[3];
    list_t *list = list_init(3, NULL);
    for (int i = 0; i < 3; i++) list_add(list, &values[i]);
    return list;
}
static void get_past_end(void *unused) {
    (void)unused;
    list_get(three_element_list(), 3);
}
static void get_huge_index(void *unused) {
    (void)unused;
    list_get(three_element_list(), SIZE_MAX);
}
static void get_from_empty(void *unused) {
    (void)unused;
    list_get(list_init(4, NULL), 0);
}
static void remove_past_end(void *unused) {
    (void)unused;
    list_remove(three_element_list(), 3);
}
static void remove_from_empty(void *unused) {
    (void)unused;
    list_remove(list_init(0, NULL), 0);
}
static void set_past_end(void *unused) {
    (void)unused;
    list_set(three_element_list(), 3, NULL);
}
static void size_of_null(void *unused) {
    (void)unused;
    list_size(NULL);
}
static void get_from_null(void *unused) {
    (void)unused;
    list_get(NULL, 0);
}
static void add_to_null(void *unused) {
    (void)unused;
    static int value;
    list_add(NULL, &value);
}
static void add_null_element(void *unused) {
    (void)unused;
    list_add(three_element_list(), NULL);
}
static void remove_from_null(void *unused) {
    (void)unused;
    list_remove(NULL, 0);
}
static void free_null(void *unused) {
    (void)unused;
    list_free(NULL);
}
static void init_overflowing_capacity(void *unused) {
    (void)unused;
    /* capacity * sizeof(void *) does not fit in a size_t. */
    static int value;
    list_t *list = list_init(SIZE_MAX / sizeof(void *) + 2, NULL);
    for (int i = 0; i < 4; i++) list_add(list, &value);
}

static void bad_input_aborts_with_message(void) {
    CHECK_DIES(get_past_end, NULL, "engine error in list_get:", "index 3 out of range", "size 3");
    CHECK_DIES(get_huge_index, NULL, "engine error in list_get:", "out of range");
    CHECK_DIES(get_from_empty, NULL, "engine error in list_get:", "index 0 out of range",
               "size 0");
    CHECK_DIES(remove_past_end, NULL, "engine error in list_remove:", "index 3 out of range");
    CHECK_DIES(remove_from_empty, NULL, "engine error in list_remove:", "out of range");
    CHECK_DIES(set_past_end, NULL, "engine error in list_set:", "out of range");
    CHECK_DIES(size_of_null, NULL, "engine error in list_size:", "NULL");
    CHECK_DIES(get_from_null, NULL, "engine error in list_get:", "NULL");
    CHECK_DIES(add_to_null, NULL, "engine error in list_add: list is NULL");
    CHECK_DIES(add_null_element, NULL, "engine error in list_add: element is NULL");
    CHECK_DIES(remove_from_null, NULL, "engine error in list_remove:", "NULL");
    CHECK_DIES(free_null, NULL, "engine error in list_free:", "NULL");
    CHECK_DIES(init_overflowing_capacity, NULL, "engine error in list_init:", "capacity");
}

TEST_SUITE(list, TEST_CASE(init_is_empty), TEST_CASE(add_and_get_keep_order),
           TEST_CASE(add_grows_past_initial_capacity), TEST_CASE(set_may_store_null),
           TEST_CASE(remove_returns_element_and_shifts),
           TEST_CASE(removed_element_belongs_to_caller),
           TEST_CASE(free_calls_freer_on_each_element), TEST_CASE(set_replaces_and_returns_old),
           TEST_CASE(bad_input_aborts_with_message));
