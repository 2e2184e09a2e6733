#include <pthread.h>
#include <string.h>
#include "fft.h"

static pthread_mutex_t planner_lock = PTHREAD_MUTEX_INITIALIZER;

rb_status rb_fft_real_init(rb_fft_real *f, size_t n)
{
    memset(f, 0, sizeof *f);
    if (n < 2 || n > (size_t)1 << 28)
        return RB_ERR_INVALID;
    f->n = n;
    f->time = fftw_malloc(n * sizeof *f->time);
    f->freq = fftw_malloc((n / 2 + 1) * sizeof *f->freq);
    if (!f->time || !f->freq) {
        rb_fft_real_free(f);
        return RB_ERR_NOMEM;
    }
    pthread_mutex_lock(&planner_lock);
    f->inverse = fftw_plan_dft_c2r_1d((int)n, f->freq, f->time,
                                      FFTW_ESTIMATE | FFTW_NO_SIMD | FFTW_DESTROY_INPUT);
    f->forward = fftw_plan_dft_r2c_1d((int)n, f->time, f->freq,
                                      FFTW_ESTIMATE | FFTW_NO_SIMD | FFTW_PRESERVE_INPUT);
    pthread_mutex_unlock(&planner_lock);
    if (!f->inverse || !f->forward) {
        rb_fft_real_free(f);
        return RB_ERR_NOMEM;
    }
    return RB_OK;
}

void rb_fft_real_inverse(rb_fft_real *f)
{
    fftw_execute(f->inverse);
}

void rb_fft_real_forward(rb_fft_real *f)
{
    fftw_execute(f->forward);
}

void rb_fft_real_free(rb_fft_real *f)
{
    if (!f)
        return;
    pthread_mutex_lock(&planner_lock);
    if (f->inverse)
        fftw_destroy_plan(f->inverse);
    if (f->forward)
        fftw_destroy_plan(f->forward);
    pthread_mutex_unlock(&planner_lock);
    fftw_free(f->time);
    fftw_free(f->freq);
    memset(f, 0, sizeof *f);
}
