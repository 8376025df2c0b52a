MODULE a_main
  ! Tests: a global PERS declared with the same name, type and initial value
  ! in two modules is one shared object: a change made through one module is
  ! seen through the other.
  PERS num shared := 4;
  PROC main()
    IncShared;
    TPWrite "shared=" \Num:=shared;
  ENDPROC
ENDMODULE
