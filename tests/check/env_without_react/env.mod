MODULE NoReaction
    ! An environment model needs a react procedure; this one has only init.
    VAR signaldi DI_GO;

    PROC init()
        SetDI DI_GO, 1;
    ENDPROC
ENDMODULE
