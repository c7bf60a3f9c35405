/* GENERATED FILE - DO NOT EDIT. C code emitted by CasADi for place_object() of
 * generated/na5/ (see its model.py), plus its batched driver.
 * Regenerate with: python -m snakecg_derive --checked-in
 * spec sha256: a2d11c24d4176a7337125b71c8295163762d302b9468a78a7f172d9e0a64cce1
 * tools: sympy 1.14.0, casadi 3.8.2, jinja2 3.1.6
 */
/* How to prefix internal symbols */
#ifdef CASADI_CODEGEN_PREFIX
  #define CASADI_NAMESPACE_CONCAT(NS, ID) _CASADI_NAMESPACE_CONCAT(NS, ID)
  #define _CASADI_NAMESPACE_CONCAT(NS, ID) NS ## ID
  #define CASADI_PREFIX(ID) CASADI_NAMESPACE_CONCAT(CODEGEN_PREFIX, ID)
#else
  #define CASADI_PREFIX(ID) snakecg_na5_place_object_ ## ID
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
#define casadi_s4 CASADI_PREFIX(s4)
#define casadi_s5 CASADI_PREFIX(s5)

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
CASADI_SYMBOL_EXPORT void snakecg_na5_place_object_casadi_version(int* major, int* minor, int* patch) {
  *major = 3;
  *minor = 8;
  *patch = 2;
}
CASADI_SYMBOL_EXPORT int snakecg_na5_place_object_casadi_int_size(void) { return (int) sizeof(casadi_int); }
CASADI_SYMBOL_EXPORT int snakecg_na5_place_object_casadi_real_size(void) { return (int) sizeof(casadi_real); }

static const casadi_int casadi_s0[3] = {8, 1, 1};
static const casadi_int casadi_s1[3] = {58, 1, 1};
static const casadi_int casadi_s2[3] = {6, 1, 1};
static const casadi_int casadi_s3[3] = {1, 1, 1};
static const casadi_int casadi_s4[3] = {3, 1, 1};
static const casadi_int casadi_s5[3] = {2, 1, 1};

/* snakecg_na5_place_object:(q[8],K[58],contact_link[6],contact_offset,object_distance,side)->(q_obj[3],rho[2],contact_point[2]) */
static int casadi_f0(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a14, a15, a16, a17, a18, a19, a20, a21, a22, a23;
  casadi_real a24, a25, a26, a27, a28, a29, a30, a31, a32, a33, a34, a35;
  casadi_real a36, a37, a38, a39, a40, a41, a42, a43, a44, a45;
  a00=arg[0]? arg[0][0] : 0;
  a01=arg[2]? arg[2][0] : 0;
  a02=(a00*a01);
  a03=arg[0]? arg[0][2] : 0;
  a04=cos(a03);
  a05=arg[1]? arg[1][6] : 0;
  a06=arg[1]? arg[1][18] : 0;
  a05=(a05-a06);
  a07=(a04*a05);
  a00=(a00+a07);
  a07=arg[0]? arg[0][3] : 0;
  a08=cos(a07);
  a09=(a04*a08);
  a10=sin(a03);
  a11=sin(a07);
  a12=(a10*a11);
  a09=(a09-a12);
  a12=arg[1]? arg[1][19] : 0;
  a13=(a09*a12);
  a00=(a00+a13);
  a13=arg[2]? arg[2][1] : 0;
  a14=(a00*a13);
  a02=(a02+a14);
  a14=arg[1]? arg[1][7] : 0;
  a14=(a14-a12);
  a15=(a09*a14);
  a00=(a00+a15);
  a15=arg[0]? arg[0][4] : 0;
  a16=cos(a15);
  a17=(a09*a16);
  a11=(a04*a11);
  a18=(a08*a10);
  a18=(a11+a18);
  a19=sin(a15);
  a20=(a18*a19);
  a20=(a17-a20);
  a21=arg[1]? arg[1][20] : 0;
  a22=(a20*a21);
  a00=(a00+a22);
  a22=arg[2]? arg[2][2] : 0;
  a23=(a00*a22);
  a02=(a02+a23);
  a23=arg[1]? arg[1][8] : 0;
  a23=(a23-a21);
  a24=(a20*a23);
  a00=(a00+a24);
  a24=arg[0]? arg[0][5] : 0;
  a25=cos(a24);
  a26=(a20*a25);
  a27=(a09*a19);
  a28=(a16*a18);
  a28=(a27+a28);
  a29=sin(a24);
  a30=(a28*a29);
  a26=(a26-a30);
  a30=arg[1]? arg[1][21] : 0;
  a31=(a26*a30);
  a00=(a00+a31);
  a31=arg[2]? arg[2][3] : 0;
  a32=(a00*a31);
  a02=(a02+a32);
  a32=arg[1]? arg[1][9] : 0;
  a32=(a32-a30);
  a33=(a26*a32);
  a00=(a00+a33);
  a33=arg[0]? arg[0][6] : 0;
  a34=cos(a33);
  a35=(a26*a34);
  a20=(a20*a29);
  a36=(a25*a28);
  a20=(a20+a36);
  a36=sin(a33);
  a37=(a20*a36);
  a35=(a35-a37);
  a37=arg[1]? arg[1][22] : 0;
  a38=(a35*a37);
  a00=(a00+a38);
  a38=arg[2]? arg[2][4] : 0;
  a39=(a00*a38);
  a02=(a02+a39);
  a39=arg[1]? arg[1][10] : 0;
  a39=(a39-a37);
  a40=(a35*a39);
  a00=(a00+a40);
  a40=arg[0]? arg[0][7] : 0;
  a41=cos(a40);
  a42=(a35*a41);
  a26=(a26*a36);
  a43=(a34*a20);
  a26=(a26+a43);
  a43=sin(a40);
  a44=(a26*a43);
  a42=(a42-a44);
  a44=arg[1]? arg[1][23] : 0;
  a42=(a42*a44);
  a00=(a00+a42);
  a42=arg[2]? arg[2][5] : 0;
  a00=(a00*a42);
  a02=(a02+a00);
  a00=arg[3]? arg[3][0] : 0;
  a06=(a06*a01);
  a45=(a12*a13);
  a06=(a06+a45);
  a45=(a21*a22);
  a06=(a06+a45);
  a45=(a30*a31);
  a06=(a06+a45);
  a45=(a37*a38);
  a06=(a06+a45);
  a45=(a44*a42);
  a06=(a06+a45);
  a00=(a00-a06);
  a04=(a01*a04);
  a09=(a13*a09);
  a04=(a04+a09);
  a08=(a10*a08);
  a08=(a08+a11);
  a19=(a08*a19);
  a17=(a17-a19);
  a19=(a22*a17);
  a04=(a04+a19);
  a19=(a17*a25);
  a16=(a08*a16);
  a16=(a16+a27);
  a27=(a16*a29);
  a19=(a19-a27);
  a27=(a31*a19);
  a04=(a04+a27);
  a27=(a19*a34);
  a25=(a16*a25);
  a17=(a17*a29);
  a25=(a25+a17);
  a17=(a25*a36);
  a27=(a27-a17);
  a17=(a38*a27);
  a04=(a04+a17);
  a17=(a27*a41);
  a34=(a25*a34);
  a19=(a19*a36);
  a34=(a34+a19);
  a19=(a34*a43);
  a17=(a17-a19);
  a17=(a42*a17);
  a04=(a04+a17);
  a17=(a00*a04);
  a02=(a02+a17);
  a17=arg[4]? arg[4][0] : 0;
  a19=arg[5]? arg[5][0] : 0;
  a36=(a01*a10);
  a08=(a13*a08);
  a36=(a36+a08);
  a16=(a22*a16);
  a36=(a36+a16);
  a25=(a31*a25);
  a36=(a36+a25);
  a25=(a38*a34);
  a36=(a36+a25);
  a34=(a34*a41);
  a27=(a27*a43);
  a34=(a34+a27);
  a34=(a42*a34);
  a36=(a36+a34);
  a34=(a19*a36);
  a34=(a17*a34);
  a34=(a02-a34);
  if (res[0]!=0) res[0][0]=a34;
  a34=arg[0]? arg[0][1] : 0;
  a27=(a34*a01);
  a05=(a05*a10);
  a34=(a34+a05);
  a12=(a18*a12);
  a34=(a34+a12);
  a12=(a34*a13);
  a27=(a27+a12);
  a14=(a14*a18);
  a34=(a34+a14);
  a21=(a28*a21);
  a34=(a34+a21);
  a21=(a34*a22);
  a27=(a27+a21);
  a23=(a23*a28);
  a34=(a34+a23);
  a30=(a20*a30);
  a34=(a34+a30);
  a30=(a34*a31);
  a27=(a27+a30);
  a32=(a32*a20);
  a34=(a34+a32);
  a37=(a26*a37);
  a34=(a34+a37);
  a37=(a34*a38);
  a27=(a27+a37);
  a39=(a39*a26);
  a34=(a34+a39);
  a35=(a35*a43);
  a41=(a41*a26);
  a35=(a35+a41);
  a35=(a35*a44);
  a34=(a34+a35);
  a34=(a34*a42);
  a27=(a27+a34);
  a00=(a00*a36);
  a27=(a27+a00);
  a04=(a19*a04);
  a04=(a17*a04);
  a04=(a27+a04);
  if (res[0]!=0) res[0][1]=a04;
  a01=(a03*a01);
  a07=(a07+a03);
  a13=(a07*a13);
  a01=(a01+a13);
  a07=(a07+a15);
  a22=(a07*a22);
  a01=(a01+a22);
  a07=(a07+a24);
  a31=(a07*a31);
  a01=(a01+a31);
  a07=(a07+a33);
  a38=(a07*a38);
  a01=(a01+a38);
  a07=(a07+a40);
  a07=(a07*a42);
  a01=(a01+a07);
  if (res[0]!=0) res[0][2]=a01;
  a01=0.;
  if (res[1]!=0) res[1][0]=a01;
  a19=(a19*a17);
  a19=(-a19);
  if (res[1]!=0) res[1][1]=a19;
  if (res[2]!=0) res[2][0]=a02;
  if (res[2]!=0) res[2][1]=a27;
  return 0;
}

CASADI_SYMBOL_EXPORT int snakecg_na5_place_object(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem){
  return casadi_f0(arg, res, iw, w, mem);
}

CASADI_SYMBOL_EXPORT int snakecg_na5_place_object_checkout(void) {
  return 0;
}

CASADI_SYMBOL_EXPORT void snakecg_na5_place_object_release(int mem) {
}

CASADI_SYMBOL_EXPORT void snakecg_na5_place_object_incref(void) {
}

CASADI_SYMBOL_EXPORT void snakecg_na5_place_object_decref(void) {
}

CASADI_SYMBOL_EXPORT casadi_int snakecg_na5_place_object_n_in(void) { return 6;}

CASADI_SYMBOL_EXPORT casadi_int snakecg_na5_place_object_n_out(void) { return 3;}

CASADI_SYMBOL_EXPORT casadi_real snakecg_na5_place_object_default_in(casadi_int i) {
  switch (i) {
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* snakecg_na5_place_object_name_in(casadi_int i) {
  switch (i) {
    case 0: return "q";
    case 1: return "K";
    case 2: return "contact_link";
    case 3: return "contact_offset";
    case 4: return "object_distance";
    case 5: return "side";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* snakecg_na5_place_object_name_out(casadi_int i) {
  switch (i) {
    case 0: return "q_obj";
    case 1: return "rho";
    case 2: return "contact_point";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* snakecg_na5_place_object_sparsity_in(casadi_int i) {
  switch (i) {
    case 0: return casadi_s0;
    case 1: return casadi_s1;
    case 2: return casadi_s2;
    case 3: return casadi_s3;
    case 4: return casadi_s3;
    case 5: return casadi_s3;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* snakecg_na5_place_object_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s4;
    case 1: return casadi_s5;
    case 2: return casadi_s5;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT int snakecg_na5_place_object_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 6;
  if (sz_res) *sz_res = 3;
  if (sz_iw) *sz_iw = 0;
  if (sz_w) *sz_w = 0;
  return 0;
}

CASADI_SYMBOL_EXPORT int snakecg_na5_place_object_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 6*sizeof(const casadi_real*);
  if (sz_res) *sz_res = 3*sizeof(casadi_real*);
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

CASADI_SYMBOL_EXPORT int snakecg_na5_batch_place_object(casadi_int n, const casadi_real** arg,
    const casadi_int* stride, casadi_real** res) {
  const casadi_real* a[6];
  casadi_real* r[3];
  casadi_int* iw = (casadi_int*) malloc(sizeof(casadi_int) * 1);
  casadi_real* w = (casadi_real*) malloc(sizeof(casadi_real) * 47);
  casadi_int i, k;
  int status = 0;
  if (!iw || !w) { free(iw); free(w); return -1; }
  for (k = 0; k < 6; ++k) a[k] = 0;
  for (k = 0; k < 3; ++k) r[k] = 0;
  for (i = 0; i < n; ++i) {
    a[0] = arg[0] + i * stride[0];
    a[1] = arg[1] + i * stride[1];
    a[2] = arg[2] + i * stride[2];
    a[3] = arg[3] + i * stride[3];
    a[4] = arg[4] + i * stride[4];
    a[5] = arg[5] + i * stride[5];
    r[0] = res[0] + i * 3;
    r[1] = res[1] + i * 2;
    r[2] = res[2] + i * 2;
    if (snakecg_na5_place_object(a, r, iw, w, 0)) { status = (int) (i + 1); break; }
  }
  free(iw);
  free(w);
  return status;
}
