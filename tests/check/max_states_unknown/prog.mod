MODULE BigCounter
    ! Counts to 10000: 20001 states, far more than --max-states 10.
    VAR num count := 0;

    PROC main()
        WHILE count < 10000 DO
            count := count + 1;
        ENDWHILE
    ENDPROC
ENDMODULE
