MODULE undo_not_on_normal_return
  ! Tests: UNDO handlers do not run when a routine ends normally (reaching
  ! ENDPROC or executing RETURN).
  PROC quiet()
    TPWrite "quiet";
  UNDO
    TPWrite "undo quiet";
  ENDPROC
  PROC early()
    RETURN;
  UNDO
    TPWrite "undo early";
  ENDPROC
  PROC main()
    quiet;
    early;
    TPWrite "end";
  ENDPROC
ENDMODULE
