MODULE MainModule
  ! Tests: Sqrt returns num; assigning it to a string variable is a static type error.
  PROC main()
    VAR string s;
    TPWrite "must not run";
    s := Sqrt(4);
  ENDPROC
ENDMODULE
