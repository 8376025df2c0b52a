MODULE HandSide
    ! A driver copied for two arms names its signals at run time ("hand_ready_" + side).
    ! With the I/O configuration loaded (--eio), a name it lacks is a real ERR_ALIASIO_DEF:
    ! the configuration holds hand_ready_R only.
    VAR signaldi hand_ready;
    VAR string side := "L";
    VAR num readies := 0;

    PROC main()
        AliasIO "hand_ready_" + side, hand_ready;
        WHILE readies < 2 DO
            IF hand_ready = 1 Incr readies;
        ENDWHILE
    ENDPROC
ENDMODULE
