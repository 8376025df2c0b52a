MODULE unknown_optional_argument
  ! Tests: an optional argument naming no parameter of the routine is a
  ! static error (RMC205).
  PROC show(num a \num Scale)
    TPWrite "a=" \Num:=a;
  ENDPROC
  PROC main()
    TPWrite "never printed";
    show 1 \Factor:=2;  ! <-- error
  ENDPROC
ENDMODULE
