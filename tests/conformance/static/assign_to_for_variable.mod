MODULE assign_to_for_variable
  ! Tests: the FOR loop variable is read-only inside the loop: assigning it
  ! is a static error (RMC207).
  PROC main()
    TPWrite "never printed";
    FOR i FROM 1 TO 3 DO
      i := i + 1;  ! <-- error
    ENDFOR
  ENDPROC
ENDMODULE
