MODULE labels_do_nothing
  ! Tests: a label is not an action: execution flows through labels that no
  ! GOTO targets; labels have their own namespace per routine (the same
  ! label name in two routines is fine).
  PROC other()
  here:
    TPWrite "other";
  ENDPROC
  PROC main()
  here:
    TPWrite "one";
  there:
    other;
    TPWrite "two";
  ENDPROC
ENDMODULE
