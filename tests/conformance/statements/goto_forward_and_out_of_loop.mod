MODULE goto_forward_and_out_of_loop
  ! Tests: GOTO forward skips statements, and GOTO may leave a WHILE loop
  ! to a label outside it.
  PROC main()
    VAR num n := 0;
    GOTO skip;
    TPWrite "skipped";
  skip:
    WHILE TRUE DO
      n := n + 1;
      IF n = 4 GOTO out;
    ENDWHILE
  out:
    TPWrite "n=" \Num:=n;
  ENDPROC
ENDMODULE
