MODULE Receiver
    ! Written for the test: the receiver sets startRob by its name.
    PERS bool startRob := FALSE;
    VAR bool go := TRUE;

    PROC main()
        WHILE TRUE DO
            WaitTime 1;
            SetDataVal "startRob", go;
        ENDWHILE
    ENDPROC
ENDMODULE
