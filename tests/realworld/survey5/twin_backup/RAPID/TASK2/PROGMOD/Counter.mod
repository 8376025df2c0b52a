MODULE Counter
    ! Background task: takes each part the feeder announces.
    PERS bool bPartReady;
    PERS num nPartsTaken := 0;

    PROC main()
        WHILE TRUE DO
            WaitUntil bPartReady;
            nPartsTaken := nPartsTaken + 1;
            bPartReady := FALSE;
        ENDWHILE
    ENDPROC
ENDMODULE
