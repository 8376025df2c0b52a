MODULE unknown_variable
  ! Tests: a reference to an undeclared data name is a static error
  ! (unknown name, RMC201): nothing runs, exit code 2.
  PROC main()
    VAR num count := 0;
    TPWrite "never printed";
    count := cuont + 1;  ! <-- error
  ENDPROC
ENDMODULE
