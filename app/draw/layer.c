#include "draw/layer.h"
#include <SDL2_gfxPrimitives.h>
#include "draw/draw.h"

void layer_free(layer_t *layer) {
    if (layer->renderer != NULL) SDL_DestroyRenderer(layer->renderer);
    if (layer->surface != NULL) SDL_FreeSurface(layer->surface);
    layer->renderer = NULL;
    layer->surface = NULL;
}

SDL_Renderer *layer_begin(layer_t *layer, int w, int h) {
    if (layer->surface == NULL || layer->surface->w != w || layer->surface->h != h) {
        layer_free(layer);
        layer->surface = SDL_CreateRGBSurfaceWithFormat(0, w, h, 32, SDL_PIXELFORMAT_ARGB8888);
        if (layer->surface == NULL) return NULL;
        SDL_SetSurfaceBlendMode(layer->surface, SDL_BLENDMODE_NONE);
        layer->renderer = SDL_CreateSoftwareRenderer(layer->surface);
        if (layer->renderer == NULL) {
            layer_free(layer);
            return NULL;
        }
    }
    SDL_FillRect(layer->surface, NULL, 0);
    draw_set_canvas(layer->renderer, layer->surface);
    return layer->renderer;
}

void layer_end(layer_t *layer, SDL_Renderer *target, SDL_Surface *canvas, SDL_Rect place) {
    SDL_RenderFlush(layer->renderer);
    if (canvas != NULL) {
        SDL_RenderFlush(target);
        SDL_BlitScaled(layer->surface, NULL, canvas, &place);
    } else {
        SDL_Texture *texture = SDL_CreateTextureFromSurface(target, layer->surface);
        if (texture != NULL) {
            SDL_RenderCopy(target, texture, NULL, &place);
            SDL_DestroyTexture(texture);
        }
    }
    draw_set_canvas(target, canvas);
}
