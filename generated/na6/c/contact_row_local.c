/* GENERATED FILE - DO NOT EDIT. C code emitted by CasADi for contact_row_local() of
 * generated/na6/ (see its model.py), plus its batched driver.
 * Regenerate with: python -m snakecg_derive --checked-in
 * spec sha256: 522fe595aab63e52670af90656908e991192d778246ab53ba223a16866b70733
 * tools: sympy 1.14.0, casadi 3.8.2, jinja2 3.1.6
 */
/* How to prefix internal symbols */
#ifdef CASADI_CODEGEN_PREFIX
  #define CASADI_NAMESPACE_CONCAT(NS, ID) _CASADI_NAMESPACE_CONCAT(NS, ID)
  #define _CASADI_NAMESPACE_CONCAT(NS, ID) NS ## ID
  #define CASADI_PREFIX(ID) CASADI_NAMESPACE_CONCAT(CODEGEN_PREFIX, ID)
#else
  #define CASADI_PREFIX(ID) snakecg_na6_contact_row_local_ ## ID
#endif

#include <math.h>

#ifndef casadi_real
#define casadi_real double
#endif

#ifndef casadi_int
#define casadi_int long long int
#endif

/* Add prefix to internal symbols */
#define casadi_f0 CASADI_PREFIX(f0)
#define casadi_s0 CASADI_PREFIX(s0)
#define casadi_s1 CASADI_PREFIX(s1)
#define casadi_s2 CASADI_PREFIX(s2)
#define casadi_s3 CASADI_PREFIX(s3)

/* Symbol visibility in DLLs */
#ifndef CASADI_SYMBOL_EXPORT
  #if defined(_WIN32) || defined(__WIN32__) || defined(__CYGWIN__)
    #if defined(STATIC_LINKED)
      #define CASADI_SYMBOL_EXPORT
    #else
      #define CASADI_SYMBOL_EXPORT __declspec(dllexport)
    #endif
  #elif defined(__GNUC__) && defined(GCC_HASCLASSVISIBILITY)
    #define CASADI_SYMBOL_EXPORT __attribute__ ((visibility ("default")))
  #else
    #define CASADI_SYMBOL_EXPORT
  #endif
#endif

/* Configuration this file was compiled with */
CASADI_SYMBOL_EXPORT void snakecg_na6_contact_row_local_casadi_version(int* major, int* minor, int* patch) {
  *major = 3;
  *minor = 8;
  *patch = 2;
}
CASADI_SYMBOL_EXPORT int snakecg_na6_contact_row_local_casadi_int_size(void) { return (int) sizeof(casadi_int); }
CASADI_SYMBOL_EXPORT int snakecg_na6_contact_row_local_casadi_real_size(void) { return (int) sizeof(casadi_real); }

static const casadi_int casadi_s0[3] = {3, 1, 1};
static const casadi_int casadi_s1[3] = {1, 1, 1};
static const casadi_int casadi_s2[3] = {2, 1, 1};
static const casadi_int casadi_s3[3] = {1, 3, 1};

/* snakecg_na6_contact_row_local:(link_pose[3],link_twist[3],link_bias[3],link_com,object_pose[3],object_twist[3],rho[2],side)->(a_link[1x3],g_obj[1x3],adot_v,gap,s) */
static int casadi_f0(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a14, a15, a16;
  a00=arg[0]? arg[0][2] : 0;
  a01=sin(a00);
  a02=arg[7]? arg[7][0] : 0;
  a03=(a01*a02);
  if (res[0]!=0) res[0][0]=a03;
  a00=cos(a00);
  a04=(a00*a02);
  a05=(-a04);
  if (res[0]!=0) res[0][1]=a05;
  a05=arg[3]? arg[3][0] : 0;
  a06=(a02*a05);
  a07=arg[4]? arg[4][2] : 0;
  a08=cos(a07);
  a09=arg[6]? arg[6][1] : 0;
  a10=(a08*a09);
  a07=sin(a07);
  a11=arg[6]? arg[6][0] : 0;
  a12=(a07*a11);
  a10=(a10+a12);
  a12=arg[4]? arg[4][1] : 0;
  a12=(a10+a12);
  a13=(a01*a05);
  a12=(a12+a13);
  a13=arg[0]? arg[0][1] : 0;
  a12=(a12-a13);
  a13=(a03*a12);
  a06=(a06-a13);
  a08=(a08*a11);
  a07=(a07*a09);
  a08=(a08-a07);
  a07=arg[4]? arg[4][0] : 0;
  a07=(a08+a07);
  a05=(a00*a05);
  a07=(a07+a05);
  a05=arg[0]? arg[0][0] : 0;
  a07=(a07-a05);
  a05=(a04*a07);
  a06=(a06-a05);
  if (res[0]!=0) res[0][2]=a06;
  a05=(-a03);
  if (res[1]!=0) res[1][0]=a05;
  if (res[1]!=0) res[1][1]=a04;
  a05=(a00*a08);
  a05=(a05*a02);
  a09=(a03*a10);
  a05=(a05+a09);
  if (res[1]!=0) res[1][2]=a05;
  a05=arg[2]? arg[2][0] : 0;
  a05=(a03*a05);
  a09=arg[2]? arg[2][2] : 0;
  a06=(a06*a09);
  a05=(a05+a06);
  a06=arg[1]? arg[1][0] : 0;
  a06=(a04*a06);
  a09=arg[1]? arg[1][2] : 0;
  a11=(a06*a09);
  a05=(a05+a11);
  a11=arg[1]? arg[1][1] : 0;
  a11=(a03*a11);
  a13=(a11*a09);
  a05=(a05+a13);
  a06=(a06+a11);
  a10=(a10*a04);
  a08=(a03*a08);
  a11=(a10-a08);
  a13=arg[5]? arg[5][2] : 0;
  a14=(a11*a13);
  a06=(a06+a14);
  a14=arg[5]? arg[5][0] : 0;
  a14=(a04*a14);
  a06=(a06-a14);
  a15=arg[5]? arg[5][1] : 0;
  a03=(a03*a15);
  a06=(a06-a03);
  a15=(a12*a04);
  a16=(a01*a07);
  a16=(a16*a02);
  a15=(a15-a16);
  a16=(a15*a09);
  a06=(a06-a16);
  a06=(a09*a06);
  a05=(a05+a06);
  a11=(a11*a09);
  a08=(a08-a10);
  a08=(a13*a08);
  a11=(a11+a08);
  a13=(a13*a11);
  a05=(a05+a13);
  a14=(a14*a09);
  a05=(a05-a14);
  a03=(a03*a09);
  a05=(a05-a03);
  a03=arg[2]? arg[2][1] : 0;
  a04=(a04*a03);
  a05=(a05-a04);
  if (res[2]!=0) res[2][0]=a05;
  if (res[3]!=0) res[3][0]=a15;
  a01=(a01*a12);
  a00=(a00*a07);
  a01=(a01+a00);
  if (res[4]!=0) res[4][0]=a01;
  return 0;
}

CASADI_SYMBOL_EXPORT int snakecg_na6_contact_row_local(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem){
  return casadi_f0(arg, res, iw, w, mem);
}

CASADI_SYMBOL_EXPORT int snakecg_na6_contact_row_local_checkout(void) {
  return 0;
}

CASADI_SYMBOL_EXPORT void snakecg_na6_contact_row_local_release(int mem) {
}

CASADI_SYMBOL_EXPORT void snakecg_na6_contact_row_local_incref(void) {
}

CASADI_SYMBOL_EXPORT void snakecg_na6_contact_row_local_decref(void) {
}

CASADI_SYMBOL_EXPORT casadi_int snakecg_na6_contact_row_local_n_in(void) { return 8;}

CASADI_SYMBOL_EXPORT casadi_int snakecg_na6_contact_row_local_n_out(void) { return 5;}

CASADI_SYMBOL_EXPORT casadi_real snakecg_na6_contact_row_local_default_in(casadi_int i) {
  switch (i) {
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* snakecg_na6_contact_row_local_name_in(casadi_int i) {
  switch (i) {
    case 0: return "link_pose";
    case 1: return "link_twist";
    case 2: return "link_bias";
    case 3: return "link_com";
    case 4: return "object_pose";
    case 5: return "object_twist";
    case 6: return "rho";
    case 7: return "side";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* snakecg_na6_contact_row_local_name_out(casadi_int i) {
  switch (i) {
    case 0: return "a_link";
    case 1: return "g_obj";
    case 2: return "adot_v";
    case 3: return "gap";
    case 4: return "s";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* snakecg_na6_contact_row_local_sparsity_in(casadi_int i) {
  switch (i) {
    case 0: return casadi_s0;
    case 1: return casadi_s0;
    case 2: return casadi_s0;
    case 3: return casadi_s1;
    case 4: return casadi_s0;
    case 5: return casadi_s0;
    case 6: return casadi_s2;
    case 7: return casadi_s1;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* snakecg_na6_contact_row_local_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s3;
    case 1: return casadi_s3;
    case 2: return casadi_s1;
    case 3: return casadi_s1;
    case 4: return casadi_s1;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT int snakecg_na6_contact_row_local_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 8;
  if (sz_res) *sz_res = 5;
  if (sz_iw) *sz_iw = 0;
  if (sz_w) *sz_w = 0;
  return 0;
}

CASADI_SYMBOL_EXPORT int snakecg_na6_contact_row_local_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 8*sizeof(const casadi_real*);
  if (sz_res) *sz_res = 5*sizeof(casadi_real*);
  if (sz_iw) *sz_iw = 0*sizeof(casadi_int);
  if (sz_w) *sz_w = 0*sizeof(casadi_real);
  return 0;
}



/* ------------------------------------------------------------------------------------------
 * GENERATED FILE - DO NOT EDIT. Batched drivers rendered from derive/templates/batch.c.j2.
 * snakecg's counterpart of CasADi's Function.map(n, "serial"): one loop in C over n samples,
 * reading inputs in place (input k of sample i at arg[k] + i * stride[k]; stride 0 broadcasts)
 * and writing dense column-major outputs contiguously (output k of sample i at
 * res[k] + i * nnz_out(k)). Returns 0 on success, the failing sample + 1 otherwise, -1 when out of memory.
 * ---------------------------------------------------------------------------------------- */
#include <stdlib.h>

CASADI_SYMBOL_EXPORT int snakecg_na6_batch_contact_row_local(casadi_int n, const casadi_real** arg,
    const casadi_int* stride, casadi_real** res) {
  const casadi_real* a[8];
  casadi_real* r[5];
  casadi_int* iw = (casadi_int*) malloc(sizeof(casadi_int) * 1);
  casadi_real* w = (casadi_real*) malloc(sizeof(casadi_real) * 18);
  casadi_int i, k;
  int status = 0;
  if (!iw || !w) { free(iw); free(w); return -1; }
  for (k = 0; k < 8; ++k) a[k] = 0;
  for (k = 0; k < 5; ++k) r[k] = 0;
  for (i = 0; i < n; ++i) {
    a[0] = arg[0] + i * stride[0];
    a[1] = arg[1] + i * stride[1];
    a[2] = arg[2] + i * stride[2];
    a[3] = arg[3] + i * stride[3];
    a[4] = arg[4] + i * stride[4];
    a[5] = arg[5] + i * stride[5];
    a[6] = arg[6] + i * stride[6];
    a[7] = arg[7] + i * stride[7];
    r[0] = res[0] + i * 3;
    r[1] = res[1] + i * 3;
    r[2] = res[2] + i * 1;
    r[3] = res[3] + i * 1;
    r[4] = res[4] + i * 1;
    if (snakecg_na6_contact_row_local(a, r, iw, w, 0)) { status = (int) (i + 1); break; }
  }
  free(iw);
  free(w);
  return status;
}
