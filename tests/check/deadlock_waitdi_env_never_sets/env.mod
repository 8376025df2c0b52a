MODULE NeverGo
    ! Drives DI_GO (so it is not a free input) and keeps it at 0.
    VAR signaldi DI_GO;

    PROC react()
        SetDI DI_GO, 0;
    ENDPROC
ENDMODULE
