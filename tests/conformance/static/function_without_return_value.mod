MODULE function_without_return_value
  ! Tests: RETURN in a FUNC requires a value of the return type; a bare
  ! RETURN is a static error (the code is not pinned).
  FUNC num f()
    RETURN;  ! <-- error
  ENDFUNC
  PROC main()
    TPWrite "never printed";
  ENDPROC
ENDMODULE
