/* GENERATED FILE - DO NOT EDIT. C code emitted by CasADi for derived_parameters() of
 * generated/na4/ (see its model.py), plus its batched driver.
 * Regenerate with: python -m snakecg_derive --checked-in
 * spec sha256: db1536eaaa55093bbe9104331da22db727d599bbbd37d742431adce08ea9331f
 * tools: sympy 1.14.0, casadi 3.8.2, jinja2 3.1.6
 */
/* How to prefix internal symbols */
#ifdef CASADI_CODEGEN_PREFIX
  #define CASADI_NAMESPACE_CONCAT(NS, ID) _CASADI_NAMESPACE_CONCAT(NS, ID)
  #define _CASADI_NAMESPACE_CONCAT(NS, ID) NS ## ID
  #define CASADI_PREFIX(ID) CASADI_NAMESPACE_CONCAT(CODEGEN_PREFIX, ID)
#else
  #define CASADI_PREFIX(ID) snakecg_na4_derived_parameters_ ## ID
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
#define casadi_sq CASADI_PREFIX(sq)

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

casadi_real casadi_sq(casadi_real x) { return x*x;}

/* Configuration this file was compiled with */
CASADI_SYMBOL_EXPORT void snakecg_na4_derived_parameters_casadi_version(int* major, int* minor, int* patch) {
  *major = 3;
  *minor = 8;
  *patch = 2;
}
CASADI_SYMBOL_EXPORT int snakecg_na4_derived_parameters_casadi_int_size(void) { return (int) sizeof(casadi_int); }
CASADI_SYMBOL_EXPORT int snakecg_na4_derived_parameters_casadi_real_size(void) { return (int) sizeof(casadi_real); }

static const casadi_int casadi_s0[3] = {5, 1, 1};
static const casadi_int casadi_s1[3] = {46, 1, 1};

/* snakecg_na4_derived_parameters:(link_mass[5],link_length[5],link_inertia[5],link_com[5])->(K[46]) */
static int casadi_f0(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a14, a15, a16, a17, a18, a19, a20, a21, a22, a23;
  casadi_real a24, a25, a26, a27, a28;
  a00=arg[0]? arg[0][0] : 0;
  if (res[0]!=0) res[0][0]=a00;
  a01=arg[0]? arg[0][1] : 0;
  if (res[0]!=0) res[0][1]=a01;
  a02=arg[0]? arg[0][2] : 0;
  if (res[0]!=0) res[0][2]=a02;
  a03=arg[0]? arg[0][3] : 0;
  if (res[0]!=0) res[0][3]=a03;
  a04=arg[0]? arg[0][4] : 0;
  if (res[0]!=0) res[0][4]=a04;
  a05=arg[1]? arg[1][0] : 0;
  if (res[0]!=0) res[0][5]=a05;
  a06=arg[1]? arg[1][1] : 0;
  if (res[0]!=0) res[0][6]=a06;
  a07=arg[1]? arg[1][2] : 0;
  if (res[0]!=0) res[0][7]=a07;
  a08=arg[1]? arg[1][3] : 0;
  if (res[0]!=0) res[0][8]=a08;
  a09=arg[1]? arg[1][4] : 0;
  if (res[0]!=0) res[0][9]=a09;
  a09=arg[2]? arg[2][0] : 0;
  if (res[0]!=0) res[0][10]=a09;
  a10=arg[2]? arg[2][1] : 0;
  if (res[0]!=0) res[0][11]=a10;
  a11=arg[2]? arg[2][2] : 0;
  if (res[0]!=0) res[0][12]=a11;
  a12=arg[2]? arg[2][3] : 0;
  if (res[0]!=0) res[0][13]=a12;
  a13=arg[2]? arg[2][4] : 0;
  if (res[0]!=0) res[0][14]=a13;
  a14=arg[3]? arg[3][0] : 0;
  if (res[0]!=0) res[0][15]=a14;
  a15=arg[3]? arg[3][1] : 0;
  if (res[0]!=0) res[0][16]=a15;
  a16=arg[3]? arg[3][2] : 0;
  if (res[0]!=0) res[0][17]=a16;
  a17=arg[3]? arg[3][3] : 0;
  if (res[0]!=0) res[0][18]=a17;
  a18=arg[3]? arg[3][4] : 0;
  if (res[0]!=0) res[0][19]=a18;
  a00=(a00+a01);
  a00=(a00+a02);
  a00=(a00+a03);
  a00=(a00+a04);
  if (res[0]!=0) res[0][20]=a00;
  a05=(a05-a14);
  a14=(a05*a01);
  a00=(a05*a02);
  a19=(a14+a00);
  a20=(a05*a03);
  a19=(a19+a20);
  a21=(a05*a04);
  a19=(a19+a21);
  if (res[0]!=0) res[0][21]=a19;
  a19=(a06*a02);
  a22=(a06*a03);
  a23=(a19+a22);
  a24=(a06*a04);
  a23=(a23+a24);
  a25=(a15*a01);
  a23=(a23+a25);
  if (res[0]!=0) res[0][22]=a23;
  a23=(a07*a03);
  a25=(a07*a04);
  a26=(a23+a25);
  a27=(a16*a02);
  a26=(a26+a27);
  if (res[0]!=0) res[0][23]=a26;
  a26=(a08*a04);
  a27=(a17*a03);
  a27=(a26+a27);
  if (res[0]!=0) res[0][24]=a27;
  a27=(a18*a04);
  if (res[0]!=0) res[0][25]=a27;
  a05=casadi_sq(a05);
  a27=(a05*a01);
  a28=(a05*a02);
  a27=(a27+a28);
  a28=(a05*a03);
  a27=(a27+a28);
  a05=(a05*a04);
  a27=(a27+a05);
  if (res[0]!=0) res[0][26]=a27;
  a14=(a14*a15);
  a05=(a00*a06);
  a14=(a14+a05);
  a05=(a20*a06);
  a14=(a14+a05);
  a05=(a21*a06);
  a14=(a14+a05);
  if (res[0]!=0) res[0][27]=a14;
  a00=(a00*a16);
  a14=(a20*a07);
  a00=(a00+a14);
  a14=(a21*a07);
  a00=(a00+a14);
  if (res[0]!=0) res[0][28]=a00;
  a20=(a20*a17);
  a00=(a21*a08);
  a20=(a20+a00);
  if (res[0]!=0) res[0][29]=a20;
  a21=(a21*a18);
  if (res[0]!=0) res[0][30]=a21;
  a06=casadi_sq(a06);
  a21=(a06*a02);
  a20=(a06*a03);
  a21=(a21+a20);
  a06=(a06*a04);
  a21=(a21+a06);
  a15=casadi_sq(a15);
  a01=(a01*a15);
  a21=(a21+a01);
  if (res[0]!=0) res[0][31]=a21;
  a19=(a19*a16);
  a01=(a22*a07);
  a19=(a19+a01);
  a01=(a24*a07);
  a19=(a19+a01);
  if (res[0]!=0) res[0][32]=a19;
  a22=(a22*a17);
  a19=(a24*a08);
  a22=(a22+a19);
  if (res[0]!=0) res[0][33]=a22;
  a24=(a24*a18);
  if (res[0]!=0) res[0][34]=a24;
  a07=casadi_sq(a07);
  a24=(a07*a03);
  a07=(a07*a04);
  a24=(a24+a07);
  a16=casadi_sq(a16);
  a02=(a02*a16);
  a24=(a24+a02);
  if (res[0]!=0) res[0][35]=a24;
  a23=(a23*a17);
  a02=(a25*a08);
  a23=(a23+a02);
  if (res[0]!=0) res[0][36]=a23;
  a25=(a25*a18);
  if (res[0]!=0) res[0][37]=a25;
  a17=casadi_sq(a17);
  a03=(a03*a17);
  a08=casadi_sq(a08);
  a08=(a04*a08);
  a03=(a03+a08);
  if (res[0]!=0) res[0][38]=a03;
  a26=(a26*a18);
  if (res[0]!=0) res[0][39]=a26;
  a18=casadi_sq(a18);
  a04=(a04*a18);
  if (res[0]!=0) res[0][40]=a04;
  a27=(a27+a09);
  if (res[0]!=0) res[0][41]=a27;
  a21=(a21+a10);
  if (res[0]!=0) res[0][42]=a21;
  a24=(a24+a11);
  if (res[0]!=0) res[0][43]=a24;
  a03=(a03+a12);
  if (res[0]!=0) res[0][44]=a03;
  a04=(a04+a13);
  if (res[0]!=0) res[0][45]=a04;
  return 0;
}

CASADI_SYMBOL_EXPORT int snakecg_na4_derived_parameters(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem){
  return casadi_f0(arg, res, iw, w, mem);
}

CASADI_SYMBOL_EXPORT int snakecg_na4_derived_parameters_checkout(void) {
  return 0;
}

CASADI_SYMBOL_EXPORT void snakecg_na4_derived_parameters_release(int mem) {
}

CASADI_SYMBOL_EXPORT void snakecg_na4_derived_parameters_incref(void) {
}

CASADI_SYMBOL_EXPORT void snakecg_na4_derived_parameters_decref(void) {
}

CASADI_SYMBOL_EXPORT casadi_int snakecg_na4_derived_parameters_n_in(void) { return 4;}

CASADI_SYMBOL_EXPORT casadi_int snakecg_na4_derived_parameters_n_out(void) { return 1;}

CASADI_SYMBOL_EXPORT casadi_real snakecg_na4_derived_parameters_default_in(casadi_int i) {
  switch (i) {
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* snakecg_na4_derived_parameters_name_in(casadi_int i) {
  switch (i) {
    case 0: return "link_mass";
    case 1: return "link_length";
    case 2: return "link_inertia";
    case 3: return "link_com";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* snakecg_na4_derived_parameters_name_out(casadi_int i) {
  switch (i) {
    case 0: return "K";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* snakecg_na4_derived_parameters_sparsity_in(casadi_int i) {
  switch (i) {
    case 0: return casadi_s0;
    case 1: return casadi_s0;
    case 2: return casadi_s0;
    case 3: return casadi_s0;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* snakecg_na4_derived_parameters_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s1;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT int snakecg_na4_derived_parameters_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 4;
  if (sz_res) *sz_res = 1;
  if (sz_iw) *sz_iw = 0;
  if (sz_w) *sz_w = 0;
  return 0;
}

CASADI_SYMBOL_EXPORT int snakecg_na4_derived_parameters_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 4*sizeof(const casadi_real*);
  if (sz_res) *sz_res = 1*sizeof(casadi_real*);
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

CASADI_SYMBOL_EXPORT int snakecg_na4_batch_derived_parameters(casadi_int n, const casadi_real** arg,
    const casadi_int* stride, casadi_real** res) {
  const casadi_real* a[4];
  casadi_real* r[1];
  casadi_int* iw = (casadi_int*) malloc(sizeof(casadi_int) * 1);
  casadi_real* w = (casadi_real*) malloc(sizeof(casadi_real) * 30);
  casadi_int i, k;
  int status = 0;
  if (!iw || !w) { free(iw); free(w); return -1; }
  for (k = 0; k < 4; ++k) a[k] = 0;
  for (k = 0; k < 1; ++k) r[k] = 0;
  for (i = 0; i < n; ++i) {
    a[0] = arg[0] + i * stride[0];
    a[1] = arg[1] + i * stride[1];
    a[2] = arg[2] + i * stride[2];
    a[3] = arg[3] + i * stride[3];
    r[0] = res[0] + i * 46;
    if (snakecg_na4_derived_parameters(a, r, iw, w, 0)) { status = (int) (i + 1); break; }
  }
  free(iw);
  free(w);
  return status;
}
