MODULE CountTo2
    ! Counts to 2, then main ends.
    VAR num x := 0;

    PROC main()
        WHILE x < 2 DO
            x := x + 1;
        ENDWHILE
    ENDPROC
ENDMODULE
