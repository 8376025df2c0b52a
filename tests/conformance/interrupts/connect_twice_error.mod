MODULE connect_twice_error
  ! Tests: CONNECT on an intnum that is already connected raises
  ! ERR_ALRDYCNT (recoverable).
  VAR intnum ir1;
  PROC main()
    CONNECT ir1 WITH tick;
    CONNECT ir1 WITH tick;
    TPWrite "after";
  ERROR
    IF ERRNO = ERR_ALRDYCNT TPWrite "already connected";
    TRYNEXT;
  ENDPROC
  TRAP tick
    TPWrite "tick";
  ENDTRAP
ENDMODULE
