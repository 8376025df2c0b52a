MODULE too_few_arguments
  ! Tests: calling a procedure with fewer required arguments than it has
  ! parameters is a static error (RMC205).
  PROC show(num a, num b)
    TPWrite "a+b=" \Num:=a + b;
  ENDPROC
  PROC main()
    TPWrite "never printed";
    show 1;  ! <-- error
  ENDPROC
ENDMODULE
