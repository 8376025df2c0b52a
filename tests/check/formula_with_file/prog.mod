MODULE CountTo3
    ! Counts to 3, then main ends.
    VAR num x := 0;

    PROC main()
        WHILE x < 3 DO
            x := x + 1;
        ENDWHILE
    ENDPROC
ENDMODULE
