MODULE a_main
  ! Tests: LOCAL data are visible only in their own module: naming another
  ! module's LOCAL VAR is an unknown name (RMC201).
  PROC main()
    TPWrite "never printed";
    TPWrite "secret=" \Num:=secret;  ! <-- error
  ENDPROC
ENDMODULE
