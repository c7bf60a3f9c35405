/* GENERATED FILE - DO NOT EDIT. C code emitted by CasADi for scene_kinematics() of
 * generated/na2/ (see its model.py), plus its batched driver.
 * Regenerate with: python -m snakecg_derive --checked-in
 * spec sha256: 1ffd02983b32fea1953b31d6b4da6e985de5a598f8e69763f0a5d6374958d5e8
 * tools: sympy 1.14.0, casadi 3.8.2, jinja2 3.1.6
 */
/* How to prefix internal symbols */
#ifdef CASADI_CODEGEN_PREFIX
  #define CASADI_NAMESPACE_CONCAT(NS, ID) _CASADI_NAMESPACE_CONCAT(NS, ID)
  #define _CASADI_NAMESPACE_CONCAT(NS, ID) NS ## ID
  #define CASADI_PREFIX(ID) CASADI_NAMESPACE_CONCAT(CODEGEN_PREFIX, ID)
#else
  #define CASADI_PREFIX(ID) snakecg_na2_scene_kinematics_ ## ID
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
CASADI_SYMBOL_EXPORT void snakecg_na2_scene_kinematics_casadi_version(int* major, int* minor, int* patch) {
  *major = 3;
  *minor = 8;
  *patch = 2;
}
CASADI_SYMBOL_EXPORT int snakecg_na2_scene_kinematics_casadi_int_size(void) { return (int) sizeof(casadi_int); }
CASADI_SYMBOL_EXPORT int snakecg_na2_scene_kinematics_casadi_real_size(void) { return (int) sizeof(casadi_real); }

static const casadi_int casadi_s0[3] = {5, 1, 1};
static const casadi_int casadi_s1[3] = {25, 1, 1};
static const casadi_int casadi_s2[3] = {3, 3, 1};
static const casadi_int casadi_s3[3] = {9, 5, 1};
static const casadi_int casadi_s4[3] = {5, 5, 1};
static const casadi_int casadi_s5[3] = {2, 3, 1};

/* snakecg_na2_scene_kinematics:(q[5],K[25])->(poses[3x3],J[9x5],M[5x5],cs[2x3]) */
static int casadi_f0(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a14, a15, a16, a17, a18, a19, a20, a21, a22, a23;
  a00=arg[0]? arg[0][0] : 0;
  if (res[0]!=0) res[0][0]=a00;
  a01=arg[0]? arg[0][1] : 0;
  if (res[0]!=0) res[0][1]=a01;
  a02=arg[0]? arg[0][2] : 0;
  if (res[0]!=0) res[0][2]=a02;
  a03=cos(a02);
  a04=arg[1]? arg[1][3] : 0;
  a05=arg[1]? arg[1][9] : 0;
  a04=(a04-a05);
  a05=(a03*a04);
  a06=(a05+a00);
  a07=arg[0]? arg[0][3] : 0;
  a08=cos(a07);
  a09=(a03*a08);
  a10=sin(a02);
  a11=sin(a07);
  a12=(a10*a11);
  a09=(a09-a12);
  a12=arg[1]? arg[1][10] : 0;
  a13=(a09*a12);
  a14=(a06+a13);
  if (res[0]!=0) res[0][3]=a14;
  a04=(a04*a10);
  a15=(a04+a01);
  a11=(a03*a11);
  a08=(a08*a10);
  a11=(a11+a08);
  a08=(a11*a12);
  a16=(a15+a08);
  if (res[0]!=0) res[0][4]=a16;
  a07=(a07+a02);
  if (res[0]!=0) res[0][5]=a07;
  a02=arg[1]? arg[1][4] : 0;
  a12=(a02-a12);
  a17=(a09*a12);
  a17=(a14+a17);
  a18=arg[0]? arg[0][4] : 0;
  a19=cos(a18);
  a20=(a09*a19);
  a21=sin(a18);
  a22=(a11*a21);
  a20=(a20-a22);
  a22=arg[1]? arg[1][11] : 0;
  a23=(a20*a22);
  a17=(a17+a23);
  if (res[0]!=0) res[0][6]=a17;
  a12=(a12*a11);
  a12=(a16+a12);
  a21=(a09*a21);
  a19=(a19*a11);
  a21=(a21+a19);
  a22=(a21*a22);
  a12=(a12+a22);
  if (res[0]!=0) res[0][7]=a12;
  a07=(a07+a18);
  if (res[0]!=0) res[0][8]=a07;
  a07=1.;
  if (res[1]!=0) res[1][0]=a07;
  a18=0.;
  if (res[1]!=0) res[1][1]=a18;
  if (res[1]!=0) res[1][2]=a18;
  if (res[1]!=0) res[1][3]=a07;
  if (res[1]!=0) res[1][4]=a18;
  if (res[1]!=0) res[1][5]=a18;
  if (res[1]!=0) res[1][6]=a07;
  if (res[1]!=0) res[1][7]=a18;
  if (res[1]!=0) res[1][8]=a18;
  if (res[1]!=0) res[1][9]=a18;
  if (res[1]!=0) res[1][10]=a07;
  if (res[1]!=0) res[1][11]=a18;
  if (res[1]!=0) res[1][12]=a18;
  if (res[1]!=0) res[1][13]=a07;
  if (res[1]!=0) res[1][14]=a18;
  if (res[1]!=0) res[1][15]=a18;
  if (res[1]!=0) res[1][16]=a07;
  if (res[1]!=0) res[1][17]=a18;
  if (res[1]!=0) res[1][18]=a18;
  if (res[1]!=0) res[1][19]=a18;
  if (res[1]!=0) res[1][20]=a07;
  a16=(a01-a16);
  if (res[1]!=0) res[1][21]=a16;
  a14=(a14-a00);
  if (res[1]!=0) res[1][22]=a14;
  if (res[1]!=0) res[1][23]=a07;
  a01=(a01-a12);
  if (res[1]!=0) res[1][24]=a01;
  a00=(a17-a00);
  if (res[1]!=0) res[1][25]=a00;
  if (res[1]!=0) res[1][26]=a07;
  if (res[1]!=0) res[1][27]=a18;
  if (res[1]!=0) res[1][28]=a18;
  if (res[1]!=0) res[1][29]=a18;
  a08=(-a08);
  if (res[1]!=0) res[1][30]=a08;
  if (res[1]!=0) res[1][31]=a13;
  if (res[1]!=0) res[1][32]=a07;
  a15=(a15-a12);
  if (res[1]!=0) res[1][33]=a15;
  a17=(a17-a06);
  if (res[1]!=0) res[1][34]=a17;
  if (res[1]!=0) res[1][35]=a07;
  if (res[1]!=0) res[1][36]=a18;
  if (res[1]!=0) res[1][37]=a18;
  if (res[1]!=0) res[1][38]=a18;
  if (res[1]!=0) res[1][39]=a18;
  if (res[1]!=0) res[1][40]=a18;
  if (res[1]!=0) res[1][41]=a18;
  a22=(-a22);
  if (res[1]!=0) res[1][42]=a22;
  if (res[1]!=0) res[1][43]=a23;
  if (res[1]!=0) res[1][44]=a07;
  a07=arg[1]? arg[1][12] : 0;
  if (res[2]!=0) res[2][0]=a07;
  if (res[2]!=0) res[2][1]=a18;
  a23=arg[1]? arg[1][15] : 0;
  a22=(a23*a21);
  a17=arg[1]? arg[1][14] : 0;
  a06=(a17*a11);
  a06=(a22+a06);
  a15=arg[1]? arg[1][13] : 0;
  a12=(a15*a10);
  a12=(a06+a12);
  a12=(-a12);
  if (res[2]!=0) res[2][2]=a12;
  a13=(-a06);
  if (res[2]!=0) res[2][3]=a13;
  a08=(-a22);
  if (res[2]!=0) res[2][4]=a08;
  if (res[2]!=0) res[2][5]=a18;
  if (res[2]!=0) res[2][6]=a07;
  a23=(a23*a20);
  a17=(a17*a09);
  a17=(a23+a17);
  a15=(a15*a03);
  a15=(a17+a15);
  if (res[2]!=0) res[2][7]=a15;
  if (res[2]!=0) res[2][8]=a17;
  if (res[2]!=0) res[2][9]=a23;
  if (res[2]!=0) res[2][10]=a12;
  if (res[2]!=0) res[2][11]=a15;
  a15=(a09*a02);
  a15=(a23*a15);
  a02=(a11*a02);
  a02=(a22*a02);
  a15=(a15+a02);
  a02=arg[1]? arg[1][24] : 0;
  a12=(a15+a02);
  a15=(a12+a15);
  a07=arg[1]? arg[1][23] : 0;
  a15=(a15+a07);
  a07=(a17*a05);
  a06=(a06*a04);
  a07=(a07+a06);
  a06=(a15+a07);
  a07=(a06+a07);
  a18=arg[1]? arg[1][22] : 0;
  a07=(a07+a18);
  if (res[2]!=0) res[2][12]=a07;
  if (res[2]!=0) res[2][13]=a06;
  a05=(a23*a05);
  a22=(a22*a04);
  a05=(a05+a22);
  a05=(a12+a05);
  if (res[2]!=0) res[2][14]=a05;
  if (res[2]!=0) res[2][15]=a13;
  if (res[2]!=0) res[2][16]=a17;
  if (res[2]!=0) res[2][17]=a06;
  if (res[2]!=0) res[2][18]=a15;
  if (res[2]!=0) res[2][19]=a12;
  if (res[2]!=0) res[2][20]=a08;
  if (res[2]!=0) res[2][21]=a23;
  if (res[2]!=0) res[2][22]=a05;
  if (res[2]!=0) res[2][23]=a12;
  if (res[2]!=0) res[2][24]=a02;
  if (res[3]!=0) res[3][0]=a03;
  if (res[3]!=0) res[3][1]=a10;
  if (res[3]!=0) res[3][2]=a09;
  if (res[3]!=0) res[3][3]=a11;
  if (res[3]!=0) res[3][4]=a20;
  if (res[3]!=0) res[3][5]=a21;
  return 0;
}

CASADI_SYMBOL_EXPORT int snakecg_na2_scene_kinematics(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem){
  return casadi_f0(arg, res, iw, w, mem);
}

CASADI_SYMBOL_EXPORT int snakecg_na2_scene_kinematics_checkout(void) {
  return 0;
}

CASADI_SYMBOL_EXPORT void snakecg_na2_scene_kinematics_release(int mem) {
}

CASADI_SYMBOL_EXPORT void snakecg_na2_scene_kinematics_incref(void) {
}

CASADI_SYMBOL_EXPORT void snakecg_na2_scene_kinematics_decref(void) {
}

CASADI_SYMBOL_EXPORT casadi_int snakecg_na2_scene_kinematics_n_in(void) { return 2;}

CASADI_SYMBOL_EXPORT casadi_int snakecg_na2_scene_kinematics_n_out(void) { return 4;}

CASADI_SYMBOL_EXPORT casadi_real snakecg_na2_scene_kinematics_default_in(casadi_int i) {
  switch (i) {
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* snakecg_na2_scene_kinematics_name_in(casadi_int i) {
  switch (i) {
    case 0: return "q";
    case 1: return "K";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* snakecg_na2_scene_kinematics_name_out(casadi_int i) {
  switch (i) {
    case 0: return "poses";
    case 1: return "J";
    case 2: return "M";
    case 3: return "cs";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* snakecg_na2_scene_kinematics_sparsity_in(casadi_int i) {
  switch (i) {
    case 0: return casadi_s0;
    case 1: return casadi_s1;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* snakecg_na2_scene_kinematics_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s2;
    case 1: return casadi_s3;
    case 2: return casadi_s4;
    case 3: return casadi_s5;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT int snakecg_na2_scene_kinematics_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 2;
  if (sz_res) *sz_res = 4;
  if (sz_iw) *sz_iw = 0;
  if (sz_w) *sz_w = 0;
  return 0;
}

CASADI_SYMBOL_EXPORT int snakecg_na2_scene_kinematics_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 2*sizeof(const casadi_real*);
  if (sz_res) *sz_res = 4*sizeof(casadi_real*);
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

CASADI_SYMBOL_EXPORT int snakecg_na2_batch_scene_kinematics(casadi_int n, const casadi_real** arg,
    const casadi_int* stride, casadi_real** res) {
  const casadi_real* a[2];
  casadi_real* r[4];
  casadi_int* iw = (casadi_int*) malloc(sizeof(casadi_int) * 1);
  casadi_real* w = (casadi_real*) malloc(sizeof(casadi_real) * 25);
  casadi_int i, k;
  int status = 0;
  if (!iw || !w) { free(iw); free(w); return -1; }
  for (k = 0; k < 2; ++k) a[k] = 0;
  for (k = 0; k < 4; ++k) r[k] = 0;
  for (i = 0; i < n; ++i) {
    a[0] = arg[0] + i * stride[0];
    a[1] = arg[1] + i * stride[1];
    r[0] = res[0] + i * 9;
    r[1] = res[1] + i * 45;
    r[2] = res[2] + i * 25;
    r[3] = res[3] + i * 6;
    if (snakecg_na2_scene_kinematics(a, r, iw, w, 0)) { status = (int) (i + 1); break; }
  }
  free(iw);
  free(w);
  return status;
}
